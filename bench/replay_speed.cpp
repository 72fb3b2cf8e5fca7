// The paper's 2arm gamepad inputs (45 s) replayed with O3 on the twin in lock-step (the
// simulated clock runs as fast as the CPU allows), as scripts/replay-paper.sh does: the twin a
// user gets, with the motor-level actuation of the shipped calibration.

#include <fmt/format.h>

#include <chrono>

#include "bridge/enable_and_home.hpp"
#include "controller/session.hpp"
#include "sections.hpp"
#include "twin/calibration_profile.hpp"
#include "twin/twin_platform.hpp"

namespace bench {

namespace {

/// Simulated over wall seconds of one replay of `inputs`.
double replayOnce(const std::vector<recording::GamepadState>& inputs) {
  twin::TwinOptions twin_options;
  twin::CalibrationProfile::shipped().applyTo(twin_options);
  twin::TwinPlatform twin(twin_options);
  bridge::enableAndHome(twin, 30.0);
  controller::ControllerOptions options;
  options.mapping.deadzone_reads_y_twice = true;  // the released controller's, as recorded
  controller::DualPlatformController control({{"twin", &twin}}, options);
  controller::SessionInputs session_inputs;
  session_inputs.inputs = inputs;
  controller::SessionOptions session_options;
  session_options.end_after_replay = true;
  controller::ControllerSession session(control, std::move(session_inputs), session_options);
  session.select(controller::Mode::ReplayInputs);
  const double start = twin.now();
  const auto wall_start = std::chrono::steady_clock::now();
  while (session.turn()) {
  }
  const std::chrono::duration<double> wall = std::chrono::steady_clock::now() - wall_start;
  return (twin.now() - start) / wall.count();
}

}  // namespace

void measureReplay(const BenchSettings& s, Report& report) {
  const auto ci = s.shared_data / "recordings/paper_2arm/2arm_ci.csv";
  if (!std::filesystem::exists(ci)) {
    report.skip("replay", "paper 2arm replay (O3, lock-step)", "../shared/data is absent");
    return;
  }
  const auto inputs = recording::readCi(ci);
  std::vector<double> factors;
  for (int i = 0; i < s.repeat; ++i) factors.push_back(replayOnce(inputs));
  report.add(atLeast("replay", "paper 2arm replay on the twin, O3, lock-step", Spread::of(factors),
                     "x real time", 100.0,
                     fmt::format("{} input rows at 500 Hz, the 1 s O3 start delay included; "
                                 "motor-level actuation; {} runs",
                                 inputs.size(), s.repeat)));
}

}  // namespace bench
