#include "twin/calibration_profile.hpp"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <fstream>
#include <stdexcept>

#include "common/yaml_view.hpp"
#include "yaml_joints.hpp"

namespace twin {

namespace {

// The file's sections and keys, for the reader and the writer alike.
constexpr const char* kActuation = "actuation";
constexpr const char* kUncertainty = "uncertainty";
constexpr const char* kCommands = "commands";
constexpr const char* kServoJrDelivered = "servo_jr_delivered";
constexpr const char* kReplay = "replay";
constexpr const char* kIterationOverhead = "iteration_overhead";
constexpr const char* kFit = "fit";

/// One arm's lists: fitted `values` (inertia > 0, gravity_error > -1, offset of either sign;
/// MotorMechanics checks the rest when a twin is built) or uncertainties (all >= 0). A profile
/// written before the offset, the jaws' faces, their compliance or the cables were fitted has
/// none: 0.
MotorMechanics readMechanics(const common::YamlView& node, bool values) {
  MotorMechanics m;
  for (std::size_t k = 0; k < MotorMechanics::kNames.size(); ++k) {
    const bool gravity = k == MotorMechanics::kGravityError;
    const bool offset = k == MotorMechanics::kOffset || k == MotorMechanics::kFace;
    const bool later = offset || k == MotorMechanics::kFaceCompliance ||
                       k == MotorMechanics::kCableFriction || k == MotorMechanics::kCableTravel;
    if (later && !node.find(MotorMechanics::kNames[k])) continue;
    const double minimum = !values ? 0.0 : gravity ? -1.0 : offset ? -INFINITY : 0.0;
    m.field(k) =
        readJoints(node[MotorMechanics::kNames[k]], minimum, values && (k == 0 || gravity));
  }
  return m;
}

ArmsMechanics readArms(const common::YamlView& node, bool values,
                       std::vector<common::LoadIssue>& warnings) {
  node.checkKeys({raven::armName(Arm::Left), raven::armName(Arm::Right)}, {true, warnings});
  for (Arm arm : raven::kArms) {
    node[raven::armName(arm)].checkKeys(
        std::span(MotorMechanics::kNames.begin(), MotorMechanics::kNames.size()), {true, warnings});
  }
  if (!warnings.empty()) throw common::LoadError(warnings);
  return {readMechanics(node[raven::armName(Arm::Left)], values),
          readMechanics(node[raven::armName(Arm::Right)], values)};
}

std::vector<double> listOf(const ArmJoints& joints) {
  return {joints.data(), joints.data() + joints.size()};
}

void emitArms(YAML::Emitter& out, const char* key, const ArmsMechanics& arms) {
  out << YAML::Key << key << YAML::Value << YAML::BeginMap;
  for (Arm arm : raven::kArms) {
    const MotorMechanics& m = arms[raven::slot(arm)];
    out << YAML::Key << std::string(raven::armName(arm)) << YAML::Value << YAML::BeginMap;
    for (std::size_t k = 0; k < MotorMechanics::kNames.size(); ++k) {
      out << YAML::Key << std::string(MotorMechanics::kNames[k]) << YAML::Value << YAML::Flow
          << listOf(m.field(k));
    }
    out << YAML::EndMap;
  }
  out << YAML::EndMap;
}

/// One section of a single key and value.
template <typename T>
void emitSection(YAML::Emitter& out, const char* section, const char* key, const T& value) {
  out << YAML::Key << section << YAML::Value << YAML::BeginMap;
  out << YAML::Key << key << YAML::Value << value;
  out << YAML::EndMap;
}

}  // namespace

CalibrationProfile CalibrationProfile::load(const std::filesystem::path& file) {
  const auto root = common::YamlView::parseFile(file);
  std::vector<common::LoadIssue> warnings;
  root.checkKeys({kActuation, kUncertainty, kCommands, kReplay, kFit}, {true, warnings});
  const auto replay = root.find(kReplay);
  if (replay) replay->checkKeys({kIterationOverhead}, {true, warnings});
  const auto commands = root.find(kCommands);
  if (commands) commands->checkKeys({kServoJrDelivered}, {true, warnings});
  if (!warnings.empty()) throw common::LoadError(warnings);

  CalibrationProfile profile;
  profile.mechanics = readArms(root[kActuation], true, warnings);
  if (const auto u = root.find(kUncertainty)) {
    profile.uncertainty = readArms(*u, false, warnings);
  } else {
    profile.uncertainty.fill(
        {ArmJoints::Zero(), ArmJoints::Zero(), ArmJoints::Zero(), ArmJoints::Zero()});
  }
  if (commands) {
    profile.servo_jr_delivered = (*commands)[kServoJrDelivered].asDouble();
    if (!(profile.servo_jr_delivered > 0.5 && profile.servo_jr_delivered <= 1.0)) {
      (*commands)[kServoJrDelivered].fail("must be within 0.5..1 (a share of the increments)");
    }
  }
  if (replay) {
    profile.iteration_overhead = (*replay)[kIterationOverhead].asDouble();
    if (profile.iteration_overhead < 0.0 || profile.iteration_overhead > 1.0) {
      (*replay)[kIterationOverhead].fail("must be within 0..1 s");
    }
  }
  return profile;
}

void CalibrationProfile::save(const std::filesystem::path& file,
                              const FitProvenance& provenance) const {
  YAML::Emitter out;
  out.SetDoublePrecision(6);
  out << YAML::BeginMap;
  emitArms(out, kActuation, mechanics);
  emitArms(out, kUncertainty, uncertainty);
  emitSection(out, kCommands, kServoJrDelivered, servo_jr_delivered);
  emitSection(out, kReplay, kIterationOverhead, iteration_overhead);
  out << YAML::Key << kFit << YAML::Value << YAML::BeginMap;
  if (!provenance.inputs.empty()) out << YAML::Key << "inputs" << YAML::Value << provenance.inputs;
  out << YAML::Key << "physical trials" << YAML::Value << provenance.physical;
  out << YAML::Key << "notes" << YAML::Value << provenance.notes;
  out << YAML::EndMap << YAML::EndMap;
  if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path());
  std::ofstream stream(file);
  stream
      << "# The Raven-II twin's actuation, fitted by raven_calibrate to physical recordings:\n"
         "# per arm and motor (shoulder, elbow, insertion, roll, wrist, jaw1, jaw2) the inertia\n"
         "# (N m s^2 per motor rad at the gearbox output), Coulomb friction (N m, plus "
         "load_friction\n"
         "# per N m applied), viscous friction (N m s/rad), the constant torque every move\n"
         "# overcomes (offset, N m: up takes coulomb + offset, down coulomb - offset), the\n"
         "# jaws' faces (rad) and their give (rad per N m), the friction beyond each arm cable\n"
         "# (N m) and the motor travel its stretch takes it up over (rad), and the gravity\n"
         "# compensation's error (fraction). Use: --calibration FILE.\n"
      << out.c_str() << "\n";
  if (!stream) throw std::runtime_error(file.string() + ": cannot write");
}

std::filesystem::path CalibrationProfile::shippedFile() {
  return std::filesystem::path(RAVEN_TWIN_CONFIG_DIR) / "raven2_calibration.yaml";
}

}  // namespace twin
