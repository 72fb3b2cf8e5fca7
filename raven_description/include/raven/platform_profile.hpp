#pragma once
// A platform profile: the kinematic parameters, home and limits of one Raven-II platform
// (the physical robot R_P or AMBF's twin R_S), loaded from YAML.

#include <filesystem>
#include <optional>
#include <string>

#include "raven/arm.hpp"
#include "raven/arm_convention.hpp"

namespace raven {

/// Lower and upper bound of every joint of one arm.
struct JointLimits {
  ArmJoints low = ArmJoints::Zero();
  ArmJoints high = ArmJoints::Zero();
};

/// Everything that differs between platforms (the paper's Table II) and what they share.
struct PlatformProfile {
  std::string name;
  std::string description;
  /// The chain this project's controller uses for both arms (reference section B).
  raven::PerArm<ArmConvention> kinematics;
  /// The physical robot's own firmware chain, as it reports poses (reference section A),
  /// in each arm's base frame; absent for simulated platforms.
  std::optional<raven::PerArm<ArmConvention>> firmware_kinematics;
  ArmJoints home = ArmJoints::Zero();
  /// Where the robot's own `home` command takes the arms (the firmware's homing target);
  /// absent: `home`.
  std::optional<ArmJoints> robot_home;
  JointLimits limits;

  const ArmConvention& arm(Arm a) const { return kinematics[slot(a)]; }
  /// The chain the platform reports Cartesian poses in: the firmware's when the profile has
  /// one, else the controller's.
  const ArmConvention& reportingArm(Arm a) const {
    const auto& chains = firmware_kinematics ? *firmware_kinematics : kinematics;
    return chains[slot(a)];
  }
  const ArmJoints& robotHome() const { return robot_home ? *robot_home : home; }
};

/// Reads a profile file; throws std::runtime_error naming the file and key on bad input.
PlatformProfile loadPlatformProfile(const std::filesystem::path& file);

/// The profiles shipped with this project: "physical" or "ambf".
PlatformProfile builtinProfile(const std::string& name);

/// Where the shipped profiles live.
std::filesystem::path profileDirectory();

/// Where this project's models live (raven2/, peg_transfer/).
std::filesystem::path modelDirectory();

/// AMBF's Raven-II meshes placed on our links (the viewer's skin): raven2/ambf_visuals.yaml.
inline std::filesystem::path ravenVisualSkin() {
  return modelDirectory() / "raven2" / "ambf_visuals.yaml";
}

}  // namespace raven
