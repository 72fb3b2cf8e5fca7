#pragma once
// The paper's gamepad mappings (../shared/reference/dual-platform-controller.md): M2 (both arms)
// and M1 (one arm), the radial deadzone, the IK choice (A: wrist-locked C_W, B: full IK), the
// wrist resets (X, Y), turning one gamepad reading into joint targets for both arms.

#include <Eigen/Geometry>
#include <array>
#include <string_view>

#include "raven/arm_kinematics.hpp"
#include "recording/gamepad_state.hpp"

namespace controller {

using raven::Arm;
using raven::ArmJoints;
using raven::ArmPair;

enum class MappingScheme { M2, M1Left, M1Right };
/// "m2", "m1-left", "m1-right" (the command-line names); throws std::invalid_argument otherwise.
MappingScheme mappingSchemeNamed(std::string_view name);
enum class IkMode { WristLocked, Full };

/// The mapping's constants, as the paper's controller has them.
struct MappingConstants {
  double deadzone = 0.15;           ///< radial on a stick; per axis for M1's wrist stick
  double divisor = 2000.0;          ///< stick value / divisor = metres per loop (0.5 mm at most)
  double trigger_full = 4.0;        ///< grasp = 1 - trigger / trigger_full
  double wrist_divisor = 10.0;      ///< M1: rad per loop = stick / wrist_divisor
  double roll_range = M_PI;         ///< M1 skips a roll increment reaching +-roll_range
  double wrist_range = M_PI / 2.0;  ///< and a wrist increment reaching +-wrist_range
  /// The released controller's radial test, as its recordings show it: sqrt(y^2 + y^2) > 0.15,
  /// so a stick pushed nearly sideways (|y| < 0.106) moves nothing. Off: the documented
  /// sqrt(x^2 + y^2). On to replay the paper's recordings faithfully.
  bool deadzone_reads_y_twice = false;
};

/// What one iteration asks of the arms.
struct MappingResult {
  ArmPair joints;
  /// Some joint target was saturated at a limit (the pad rumbles).
  bool clamped = false;
  /// IK found no solution for an arm: that arm keeps its previous target.
  raven::PerArm<bool> unreachable{};
};

/// The mapping's state between iterations: the scheme, the IK mode, and per arm the open-loop
/// targets (wrist point P5 for C_W, tool pose for full IK), the stored wrist values and grasp.
class GamepadMapping {
 public:
  /// Kinematics in the controller's convention (section B) of `profile`; starts in `scheme`
  /// with the wrist-locked IK, targets read from `joints`.
  GamepadMapping(const raven::PlatformProfile& profile, MappingScheme scheme, const ArmPair& joints,
                 MappingConstants constants = {});

  /// Re-reads the pose: targets, stored wrist values and grasp from `joints`.
  void reset(const ArmPair& joints);
  /// One manual-loop iteration. `measured` is read when A asks to re-read the pose.
  MappingResult apply(const recording::GamepadState& pad, const ArmPair& measured);

  MappingScheme scheme() const { return scheme_; }
  IkMode ikMode() const { return ik_mode_; }
  const ArmPair& targets() const { return joints_; }
  const MappingConstants& constants() const { return constants_; }

  /// The radial deadzone test: is the stick (x, y) outside the deadzone?
  bool outsideDeadzone(double x, double y) const;

 private:
  /// Per arm: the open-loop targets and the values C_W keeps.
  struct ArmTarget {
    Eigen::Vector3d wrist_point;
    Eigen::Isometry3d tool;
    double roll = 0.0, wrist = 0.0;  ///< joints 4 and 5
    double jaw_difference = 0.0;     ///< jaw1 - jaw2 (the grasper's orientation)
    double grasp = 0.0;              ///< jaw1 + jaw2
  };

  void selectScheme(const recording::GamepadState& pad);
  /// Moves `arm`'s target by the stick (x, y), or along z when `bumper` is held.
  void translate(Arm arm, double x, double y, bool bumper);
  /// M1's right stick on the selected arm: joint 4 by -rx / wrist_divisor, joint 5 by
  /// +ry / wrist_divisor, each past its own deadzone; a step reaching the range is skipped.
  void turnWrist(Arm arm, double rx, double ry);
  /// Solves `arm`'s joints for its targets; false if unreachable.
  bool solve(Arm arm, IkMode mode, MappingResult& result);

  raven::PlatformProfile profile_;
  raven::PerArm<raven::ArmKinematics> kinematics_;
  MappingConstants constants_;
  MappingScheme scheme_;
  IkMode ik_mode_ = IkMode::WristLocked;
  ArmPair joints_;
  raven::PerArm<ArmTarget> targets_;
};

}  // namespace controller
