#include "twin/calibration_profile.hpp"

#include "common/yaml_view.hpp"
#include "yaml_joints.hpp"

namespace twin {

CalibrationProfile CalibrationProfile::load(const std::filesystem::path& file) {
  const auto root = common::YamlView::parseFile(file);
  std::vector<common::LoadIssue> warnings;
  root.checkKeys({"tracking", "replay", "fit"}, {true, warnings});
  const auto node = root["tracking"];
  node.checkKeys({"latency_cycles", "bandwidth_hz", "damping_ratio", "friction_deadband",
                  "max_velocity", "max_acceleration"},
                 {true, warnings});
  const auto replay = root.find("replay");
  if (replay) replay->checkKeys({"iteration_overhead"}, {true, warnings});
  if (!warnings.empty()) throw common::LoadError(warnings);

  CalibrationProfile profile;
  TrackingParams& t = profile.tracking;
  t.latency_cycles = node["latency_cycles"].asDouble();
  if (t.latency_cycles < 0.0 || t.latency_cycles > TrackingParams::kMaxLatencyCycles) {
    node["latency_cycles"].fail("must be within 0.." +
                                std::to_string(TrackingParams::kMaxLatencyCycles));
  }
  t.bandwidth_hz = readJoints(node["bandwidth_hz"], 0.0, true);
  t.damping_ratio = readJoints(node["damping_ratio"], 0.0, true);
  if (auto f = node.find("friction_deadband")) t.friction_deadband = readJoints(*f, 0.0, false);
  if (auto v = node.find("max_velocity")) t.max_velocity = readJoints(*v, 0.0, true);
  if (auto a = node.find("max_acceleration")) t.max_acceleration = readJoints(*a, 0.0, true);
  if (replay) {
    profile.iteration_overhead = (*replay)["iteration_overhead"].asDouble();
    if (profile.iteration_overhead < 0.0 || profile.iteration_overhead > 1.0) {
      (*replay)["iteration_overhead"].fail("must be within 0..1 s");
    }
  }
  return profile;
}

}  // namespace twin
