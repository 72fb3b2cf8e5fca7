// Cost of C_V, the velocity-capped interpolation: planning a move of both arms and producing
// every step of it.

#include <benchmark/benchmark.h>

#include "controller/velocity_cap.hpp"
#include "raven/platform_profile.hpp"

namespace {

void BM_PlanAndStepAMove(benchmark::State& state) {
  const auto home = raven::builtinProfile("physical").home;
  const controller::ArmPair start{home, home};
  controller::ArmPair next = start;
  next[0][0] += 0.05;  // 50 mrad of shoulder: 20 steps at 500 Hz under the 1.25 rad/s cap
  next[1][2] -= 0.004;
  const controller::VelocityCaps caps;
  for (auto _ : state) {
    const auto plan = controller::planMove(start, next, caps, 1.0 / 500.0);
    for (int k = 1; k <= plan.steps; ++k) benchmark::DoNotOptimize(plan.at(k));
  }
}
BENCHMARK(BM_PlanAndStepAMove);

}  // namespace
