#include "calibration/calibration_file.hpp"

#include <yaml-cpp/yaml.h>

#include <fstream>
#include <stdexcept>

namespace calibration {

namespace {

std::vector<double> listOf(const raven::ArmJoints& joints) {
  return {joints.data(), joints.data() + joints.size()};
}

}  // namespace

void writeCalibration(const std::filesystem::path& file, const twin::CalibrationProfile& profile,
                      const FitProvenance& provenance) {
  const twin::TrackingParams& tracking = profile.tracking;
  YAML::Emitter out;
  out.SetDoublePrecision(6);
  out << YAML::BeginMap;
  out << YAML::Key << "tracking" << YAML::Value << YAML::BeginMap;
  out << YAML::Key << "latency_cycles" << YAML::Value << tracking.latency_cycles;
  out << YAML::Key << "bandwidth_hz" << YAML::Value << YAML::Flow << listOf(tracking.bandwidth_hz);
  out << YAML::Key << "damping_ratio" << YAML::Value << YAML::Flow
      << listOf(tracking.damping_ratio);
  out << YAML::Key << "friction_deadband" << YAML::Value << YAML::Flow
      << listOf(tracking.friction_deadband);
  out << YAML::EndMap;
  out << YAML::Key << "replay" << YAML::Value << YAML::BeginMap;
  out << YAML::Key << "iteration_overhead" << YAML::Value << profile.iteration_overhead;
  out << YAML::EndMap;
  out << YAML::Key << "fit" << YAML::Value << YAML::BeginMap;
  out << YAML::Key << "inputs" << YAML::Value << provenance.inputs;
  out << YAML::Key << "physical trials" << YAML::Value << provenance.physical;
  out << YAML::Key << "notes" << YAML::Value << provenance.notes;
  out << YAML::EndMap << YAML::EndMap;
  if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path());
  std::ofstream stream(file);
  stream << "# A tracking response for the Raven-II twin, fitted by raven_calibrate to physical\n"
            "# replays. Use: raven_controller --calibration FILE, raven_twin_node --calibration "
            "FILE.\n"
         << out.c_str() << "\n";
  if (!stream) throw std::runtime_error(file.string() + ": cannot write");
}

}  // namespace calibration
