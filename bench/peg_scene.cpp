#include "peg_scene.hpp"

#include "scenario/peg_transfer.hpp"

namespace bench {

std::vector<double> pegScene(const std::filesystem::path& launch, bridge::ClockKind clock,
                             bool sleep, double seconds, int repeat,
                             const scenario::WorldObserver& observe) {
  std::vector<double> rates;
  for (int i = 0; i < repeat; ++i) {
    scenario::PegTransferOptions options;
    options.assist = scenario::AssistMode::Contact;
    options.launch_file = launch;
    options.clock = clock;
    options.soft_body_sleep = sleep;
    options.time_limit = seconds;
    options.settle_time = 0.0;
    options.observe = observe;
    rates.push_back(scenario::runPegTransfer(options).timing.loopFrequency());
  }
  return rates;
}

}  // namespace bench
