#include "peg_scene.hpp"

#include <chrono>

namespace bench {

std::vector<PegSceneRate> pegScene(const PegSceneRun& run, int repeat) {
  using Clock = std::chrono::steady_clock;
  std::vector<PegSceneRate> rates;
  for (int i = 0; i < repeat; ++i) {
    scenario::PegTransferOptions options;
    options.assist = run.assist;
    options.launch_file = run.launch;
    options.clock = run.clock;
    options.soft_body_sleep = run.sleep;
    options.time_limit = run.seconds;
    options.settle_time = 0.0;
    options.observe = run.observe;
    options.squeeze = run.squeeze;
    // Iterations in which both arms held a ring from start to end: their simulated and wall time.
    double held_sim = 0.0, held_wall = 0.0;
    scenario::RunProgress last{};
    Clock::time_point last_at = Clock::now();
    options.progress = [&](const scenario::RunProgress& now) {
      const Clock::time_point at = Clock::now();
      if (last.carrying == 2 && now.carrying == 2) {
        held_sim += now.sim_time - last.sim_time;
        held_wall += std::chrono::duration<double>(at - last_at).count();
      }
      last = now;
      last_at = at;
    };
    const auto result = scenario::runPegTransfer(options);
    const double step = result.timing.sim_time / static_cast<double>(result.timing.steps);
    rates.push_back(
        {result.timing.loopFrequency(), held_wall > 0.0 ? held_sim / step / held_wall : 0.0});
  }
  return rates;
}

std::vector<double> wholeRates(const std::vector<PegSceneRate>& rates) {
  std::vector<double> out;
  for (const auto& r : rates) out.push_back(r.whole);
  return out;
}

}  // namespace bench
