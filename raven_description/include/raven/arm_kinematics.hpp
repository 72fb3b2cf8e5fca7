#pragma once
// Forward and inverse kinematics of one Raven-II arm: FK to the wrist point P5 and the tool
// point, the full closed-form IK, the wrist-locked IK C_W, joint <-> DH conversion and clamping.

#include <array>
#include <optional>
#include <vector>

#include "raven/arm.hpp"
#include "raven/arm_convention.hpp"
#include "raven/platform_profile.hpp"

namespace raven {

/// The DH variables of one arm: theta1, theta2, d3 (insertion), theta4, theta5, theta6.
using DhValues = Eigen::Matrix<double, 6, 1>;

/// Which joints a clamp moved onto their limits.
struct ClampReport {
  std::array<bool, kJointCount> clamped{};
  bool any() const;
};

/// The outcome of an inverse-kinematics request.
struct IkSolution {
  bool ok = false;                       ///< false: unreachable, or every candidate too far
  ArmJoints joints = ArmJoints::Zero();  ///< within the limits when ok
  ClampReport clamp;                     ///< what saturation to the limits changed
  double distance = 0.0;                 ///< weighted distance of the choice from the reference
};

/// One arm in one convention. Poses are in the convention's reporting frame ({B} for the
/// controller's chain). The tool point is the origin of the frame after DH row 5 (on the jaw
/// axis); P5, the wrist point, is the origin of the frame after row 4.
class ArmKinematics {
 public:
  ArmKinematics(const ArmConvention& convention, const JointLimits& limits);
  /// The controller-convention kinematics of `arm` on `profile`.
  static ArmKinematics of(const PlatformProfile& profile, Arm arm);

  DhValues toDh(const ArmJoints& q) const;
  /// Joints for `dh` with jaw opening `grasp` (jaw1 + jaw2); every revolute joint is taken at
  /// the turn nearest to `near`.
  ArmJoints fromDh(const DhValues& dh, double grasp, const ArmJoints& near) const;

  /// Frames after DH rows 0..5.
  std::array<Eigen::Isometry3d, 6> frames(const ArmJoints& q) const;
  Eigen::Isometry3d toolPose(const ArmJoints& q) const;
  Eigen::Vector3d wristPoint(const ArmJoints& q) const;
  /// The tool's twist (reporting frame) when the joints at `q` move at `qdot`: the tool point's
  /// velocity (m/s), then the angular velocity (rad/s). CRTK's measured_cv.
  Eigen::Matrix<double, 6, 1> toolTwist(const ArmJoints& q, const ArmJoints& qdot) const;

  /// Every exact solution for the tool pose (up to 8: two jaw-axis placements, two insertion
  /// signs, two elbows), unclamped, each revolute joint at the turn nearest `near`.
  std::vector<ArmJoints> inverseCandidates(const Eigen::Isometry3d& tool, double grasp,
                                           const ArmJoints& near) const;
  /// The candidate within the limits nearest `near` (ArmKinematics::distance); none if no
  /// candidate is within them.
  std::optional<ArmJoints> inverseWithinLimits(const Eigen::Isometry3d& tool, double grasp,
                                               const ArmJoints& near) const;
  /// The candidate closest to `current` (insertion weighted x100), rejected when that distance
  /// exceeds pi, then saturated to the limits.
  IkSolution inverse(const Eigen::Isometry3d& tool, double grasp, const ArmJoints& current) const;
  /// Wrist-locked IK C_W: shoulder, elbow and insertion place P5 at `wrist_point` (of four
  /// candidates, the closest to `preferred`); roll, wrist and jaws are copied from `current`
  /// unchanged. Saturated to the limits.
  IkSolution inverseWristLocked(const Eigen::Vector3d& wrist_point, const ArmJoints& current,
                                const ArmJoints& preferred) const;

  /// Saturates `q` to the limits and says which joints it moved.
  ClampReport clamp(ArmJoints& q) const;
  /// Sum of joint differences with the insertion weighted x100 (the firmware's choice rule).
  static double distance(const ArmJoints& a, const ArmJoints& b);

  const ArmConvention& convention() const { return c_; }
  const JointLimits& limits() const { return limits_; }

 private:
  /// Shoulder and elbow DH angles that point the insertion axis along the unit vector `axis`
  /// (in the frame before row 0): up to two elbow branches.
  std::vector<std::array<double, 2>> aimShaft(const Eigen::Vector3d& axis) const;

  ArmConvention c_;
  JointLimits limits_;
};

}  // namespace raven
