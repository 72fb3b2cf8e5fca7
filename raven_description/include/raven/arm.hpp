#pragma once
// The Raven-II's two arms and the per-arm joint vector shared by every layer.

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <string_view>

namespace raven {

/// Arm 0 is the left ("gold") arm, arm 1 the right ("green") arm.
enum class Arm { Left = 0, Right = 1 };

inline constexpr std::array<Arm, 2> kArms{Arm::Left, Arm::Right};
inline constexpr int kJointCount = 7;

/// Per arm, always in this order: shoulder, elbow, insertion (m), roll, wrist, jaw 1, jaw 2.
using ArmJoints = Eigen::Matrix<double, kJointCount, 1>;

enum JointIndex { kShoulder = 0, kElbow, kInsertion, kRoll, kWrist, kJaw1, kJaw2 };

inline constexpr std::array<std::string_view, kJointCount> kJointNames{
    "shoulder", "elbow", "insertion", "roll", "wrist", "jaw1", "jaw2"};

constexpr int index(Arm arm) {
  return static_cast<int>(arm);
}
constexpr Arm other(Arm arm) {
  return arm == Arm::Left ? Arm::Right : Arm::Left;
}
/// One value per arm, the left first: the container every room keeps its two arms' things in.
template <typename T>
using PerArm = std::array<T, 2>;
/// Both arms' joint vectors.
using ArmPair = PerArm<ArmJoints>;
/// The arm's place in a PerArm.
constexpr std::size_t slot(Arm arm) {
  return static_cast<std::size_t>(arm);
}

inline std::string_view armName(Arm arm) {
  return arm == Arm::Left ? "left" : "right";
}

/// `q` with its jaws opened to `opening` (jaw1 + jaw2, rad), their difference (the grasper's
/// orientation) kept.
inline ArmJoints withJawOpening(ArmJoints q, double opening) {
  const double difference = q(kJaw1) - q(kJaw2);
  q(kJaw1) = 0.5 * (opening + difference);
  q(kJaw2) = 0.5 * (opening - difference);
  return q;
}

}  // namespace raven
