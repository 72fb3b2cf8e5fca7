#include "twin/calibration_profile.hpp"

#include "common/yaml_view.hpp"
#include "yaml_joints.hpp"

namespace twin {

namespace {

/// One arm's lists: fitted `values` (inertia > 0, gravity_error > -1; MotorMechanics checks the
/// rest when a twin is built) or uncertainties (all >= 0).
MotorMechanics readMechanics(const common::YamlView& node, bool values) {
  MotorMechanics m;
  for (std::size_t k = 0; k < MotorMechanics::kNames.size(); ++k) {
    const auto field = node[MotorMechanics::kNames[k]];
    const bool gravity = k == MotorMechanics::kGravityError;
    m.field(k) = readJoints(field, values && gravity ? -1.0 : 0.0, values && (k == 0 || gravity));
  }
  return m;
}

ArmsMechanics readArms(const common::YamlView& node, bool values,
                       std::vector<common::LoadIssue>& warnings) {
  node.checkKeys({"left", "right"}, {true, warnings});
  for (const char* arm : {"left", "right"}) {
    node[arm].checkKeys(std::span(MotorMechanics::kNames.begin(), MotorMechanics::kNames.size()),
                        {true, warnings});
  }
  if (!warnings.empty()) throw common::LoadError(warnings);
  return {readMechanics(node["left"], values), readMechanics(node["right"], values)};
}

}  // namespace

CalibrationProfile CalibrationProfile::load(const std::filesystem::path& file) {
  const auto root = common::YamlView::parseFile(file);
  std::vector<common::LoadIssue> warnings;
  root.checkKeys({"actuation", "uncertainty", "commands", "replay", "fit"}, {true, warnings});
  const auto replay = root.find("replay");
  if (replay) replay->checkKeys({"iteration_overhead"}, {true, warnings});
  const auto commands = root.find("commands");
  if (commands) commands->checkKeys({"servo_jr_delivered"}, {true, warnings});
  if (!warnings.empty()) throw common::LoadError(warnings);

  CalibrationProfile profile;
  profile.mechanics = readArms(root["actuation"], true, warnings);
  if (const auto u = root.find("uncertainty")) {
    profile.uncertainty = readArms(*u, false, warnings);
  } else {
    profile.uncertainty.fill(
        {ArmJoints::Zero(), ArmJoints::Zero(), ArmJoints::Zero(), ArmJoints::Zero()});
  }
  if (commands) {
    profile.servo_jr_delivered = (*commands)["servo_jr_delivered"].asDouble();
    if (!(profile.servo_jr_delivered > 0.5 && profile.servo_jr_delivered <= 1.0)) {
      (*commands)["servo_jr_delivered"].fail("must be within 0.5..1 (a share of the increments)");
    }
  }
  if (replay) {
    profile.iteration_overhead = (*replay)["iteration_overhead"].asDouble();
    if (profile.iteration_overhead < 0.0 || profile.iteration_overhead > 1.0) {
      (*replay)["iteration_overhead"].fail("must be within 0..1 s");
    }
  }
  return profile;
}

void CalibrationProfile::applyTo(TwinOptions& options) const {
  options.motors = mechanics;
  options.limits.servo_jr_delivered = servo_jr_delivered;
}

std::filesystem::path CalibrationProfile::shippedFile() {
  return std::filesystem::path(RAVEN_TWIN_CONFIG_DIR) / "raven2_calibration.yaml";
}

}  // namespace twin
