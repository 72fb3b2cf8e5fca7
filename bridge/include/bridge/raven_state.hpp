#pragma once
// Every field of the robot's raven_2/raven_state message, in the robot's own units and layout,
// so a recorder sees the same columns whichever platform filled them.

#include <array>
#include <cstdint>

#include "raven/arm.hpp"

namespace bridge {

/// One `ravenstate` sample. Angles in DEGREES (the insertion too: metres * 180/pi), positions in
/// MICRONS, 16-element arrays indexed gold (left) 0..7 then green (right) 8..15 in the order
/// shoulder, elbow, insertion, (not connected), roll, wrist, jaw 1, jaw 2.
struct RavenStateSnapshot {
  double time = 0.0;  ///< the platform's clock (s); the header stamp on ROS
  std::int32_t runlevel = 0;
  std::int32_t sublevel = 0;
  std::int32_t last_seq = 0;
  raven::PerArm<std::int32_t> type{};
  std::array<std::int32_t, 6> pos{};  ///< tool point, gold xyz then green xyz (microns)
  std::array<float, 18> ori{};        ///< row-major tool rotations, arm j at j*9
  std::array<float, 18> ori_d{};
  std::array<std::int32_t, 6> pos_d{};
  double dt = 0.0;  ///< the cycle (s)
  std::array<std::int32_t, 16> enc_vals{};
  std::array<std::int32_t, 16> dac_val{};
  std::array<float, 16> tau{};  ///< joint torque (N m) or insertion force (N)
  std::array<float, 16> mpos{};
  std::array<float, 16> jpos{};
  std::array<float, 16> mvel{};
  std::array<float, 16> jvel{};
  std::array<float, 16> mpos_d{};
  std::array<float, 16> jpos_d{};
  raven::PerArm<float> grasp_d{};  ///< desired grasper opening per arm (degrees)
  std::array<float, 16> encoffsets{};
  std::array<float, 12> jac_vel{};  ///< per arm: tool linear (m/s) then angular (rad/s) velocity
  std::array<float, 12> jac_f{};
};

/// The robot's runlevels (RL_E_STOP .. RL_PEDAL_DN).
enum RavenRunlevel : std::int32_t { kEStop = 0, kInit = 1, kPedalUp = 2, kPedalDown = 3 };

/// The arm type codes the robot reports in `type` (its USB boards' serial numbers).
inline constexpr std::int32_t kGoldArmType = 24;
inline constexpr std::int32_t kGreenArmType = 10;

/// Index into the 16-element arrays of arm `arm`'s joint `joint` (0..6 in ArmJoints order).
inline int ravenStateIndex(raven::Arm arm, int joint) {
  return raven::index(arm) * 8 + (joint < raven::kRoll ? joint : joint + 1);
}

}  // namespace bridge
