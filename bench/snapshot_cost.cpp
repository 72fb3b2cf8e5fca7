// What a learner's snapshot costs: saving and restoring a peg-transfer episode (the world, the
// twin, the controller, the expert) against resetting it, which builds the world again.

#include <fmt/format.h>

#include <chrono>

#include "scenario/peg_transfer_env.hpp"
#include "sections.hpp"

namespace bench {

namespace {

const char* kSection = "snapshots";
constexpr int kTimes = 20;

/// Seconds `call` takes, the median of kTimes calls.
template <typename Call>
double medianSeconds(Call&& call) {
  std::vector<double> seconds;
  for (int i = 0; i < kTimes; ++i) {
    const auto start = std::chrono::steady_clock::now();
    call();
    seconds.push_back(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  return Spread::of(seconds).median;
}

}  // namespace

void measureSnapshots(const BenchSettings& s, Report& report) {
  scenario::PegTransferEnvOptions options;
  options.action = scenario::EnvAction::JointDeltas;
  options.randomize = true;
  scenario::PegTransferEnv env(options);
  std::vector<double> reset, save, restore, fraction;
  for (int r = 0; r < s.repeat; ++r) {
    reset.push_back(medianSeconds([&] { env.reset(7); }));
    for (int k = 0; k < 200; ++k) env.step(env.expertAction());  // the jaws at the first rings
    std::shared_ptr<const scenario::PegTransferEnv::State> state;
    save.push_back(medianSeconds([&] { state = env.saveState(); }));
    restore.push_back(medianSeconds([&] { env.restoreState(*state); }));
    fraction.push_back(restore.back() / reset.back());
  }
  const auto ms = [](std::vector<double> seconds) {
    for (double& v : seconds) v *= 1e3;
    return Spread::of(seconds);
  };
  const std::string how = fmt::format(
      "the randomised peg transfer, seed 7, 200 expert steps in; median of {} calls "
      "a run, {} runs",
      kTimes, s.repeat);
  report.add(measured(kSection, "reset (the world built again, homed)", ms(reset), "ms", how));
  report.add(measured(kSection, "save_state", ms(save), "ms", how));
  report.add(measured(kSection, "restore_state", ms(restore), "ms", how));
  report.add(atMost(kSection, "restore_state / reset", Spread::of(fraction), "", 0.1,
                    "a small fraction of a reload (issue 48)"));
}

}  // namespace bench
