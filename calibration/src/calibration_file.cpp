#include "calibration/calibration_file.hpp"

#include <yaml-cpp/yaml.h>

#include <fstream>
#include <stdexcept>

namespace calibration {

namespace {

std::vector<double> listOf(const raven::ArmJoints& joints) {
  return {joints.data(), joints.data() + joints.size()};
}

void emitArms(YAML::Emitter& out, const char* key, const twin::ArmsMechanics& arms) {
  out << YAML::Key << key << YAML::Value << YAML::BeginMap;
  for (raven::Arm arm : raven::kArms) {
    const twin::MotorMechanics& m = arms[raven::slot(arm)];
    out << YAML::Key << std::string(raven::armName(arm)) << YAML::Value << YAML::BeginMap;
    for (std::size_t k = 0; k < twin::MotorMechanics::kNames.size(); ++k) {
      out << YAML::Key << std::string(twin::MotorMechanics::kNames[k]) << YAML::Value << YAML::Flow
          << listOf(m.field(k));
    }
    out << YAML::EndMap;
  }
  out << YAML::EndMap;
}

}  // namespace

void writeCalibration(const std::filesystem::path& file, const twin::CalibrationProfile& profile,
                      const FitProvenance& provenance) {
  YAML::Emitter out;
  out.SetDoublePrecision(6);
  out << YAML::BeginMap;
  emitArms(out, "actuation", profile.mechanics);
  emitArms(out, "uncertainty", profile.uncertainty);
  out << YAML::Key << "commands" << YAML::Value << YAML::BeginMap;
  out << YAML::Key << "servo_jr_delivered" << YAML::Value << profile.servo_jr_delivered;
  out << YAML::EndMap;
  out << YAML::Key << "replay" << YAML::Value << YAML::BeginMap;
  out << YAML::Key << "iteration_overhead" << YAML::Value << profile.iteration_overhead;
  out << YAML::EndMap;
  out << YAML::Key << "fit" << YAML::Value << YAML::BeginMap;
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
         "# per N m applied), viscous friction (N m s/rad) and the gravity compensation's error\n"
         "# (fraction). Use: --calibration FILE.\n"
      << out.c_str() << "\n";
  if (!stream) throw std::runtime_error(file.string() + ": cannot write");
}

}  // namespace calibration
