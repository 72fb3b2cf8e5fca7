// Cost of the Raven-II kinematics the controller runs every iteration: forward kinematics, full
// inverse kinematics, and the wrist-locked inverse C_W uses.

#include <benchmark/benchmark.h>

#include "raven/arm_kinematics.hpp"
#include "raven/platform_profile.hpp"

namespace {

struct LeftArm {
  raven::PlatformProfile profile = raven::builtinProfile("physical");
  raven::ArmKinematics kin = raven::ArmKinematics::of(profile, raven::Arm::Left);
  raven::ArmJoints home = profile.home;
};

void BM_ForwardKinematics(benchmark::State& state) {
  const LeftArm arm;
  for (auto _ : state) benchmark::DoNotOptimize(arm.kin.toolPose(arm.home));
}
BENCHMARK(BM_ForwardKinematics);

void BM_InverseKinematics(benchmark::State& state) {
  const LeftArm arm;
  const auto tool = arm.kin.toolPose(arm.home);
  const double grasp = arm.home[raven::kJaw1] + arm.home[raven::kJaw2];
  for (auto _ : state) benchmark::DoNotOptimize(arm.kin.inverse(tool, grasp, arm.home));
}
BENCHMARK(BM_InverseKinematics);

void BM_InverseKinematicsWristLocked(benchmark::State& state) {
  const LeftArm arm;
  const Eigen::Vector3d wrist = arm.kin.wristPoint(arm.home) + Eigen::Vector3d(0.0005, 0, 0);
  for (auto _ : state)
    benchmark::DoNotOptimize(arm.kin.inverseWristLocked(wrist, arm.home, arm.home));
}
BENCHMARK(BM_InverseKinematicsWristLocked);

}  // namespace
