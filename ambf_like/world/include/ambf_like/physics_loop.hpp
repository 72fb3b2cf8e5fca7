#pragma once
// The dynamic loop around a World: paced to a wall-clock rate, free-running, or lock-stepped.

#include <chrono>
#include <cstdint>
#include <functional>

#include "ambf_like/frequency_meter.hpp"
#include "ambf_like/world.hpp"

namespace ambf_like {

/// How the loop advances (AMBF's `-p` and `-t`).
struct LoopOptions {
  double rate_hz = 1.0 / kAmbfStepSize;  ///< outer iterations per second (AMBF `-p`)
  bool paced = true;            ///< sleep to hold rate_hz; false: run as fast as the CPU allows
  bool fixed_time_step = true;  ///< each iteration advances 1/rate_hz (AMBF `-t`); false: the
                                ///< simulation catches up with the wall clock, within the
                                ///< world's max iterations
};

/// Runs a World's outer loop and measures its frequency. One iteration may hold several
/// fixed internal steps (1/rate_hz divided by the step size).
class PhysicsLoop {
 public:
  using Clock = FrequencyMeter::Clock;

  PhysicsLoop(World& world, LoopOptions options);

  /// One outer iteration: wait for its tick when paced, then advance the world.
  void iterate();
  /// Lock-step with an external simulated clock: step until the world reaches `sim_time`.
  /// Each internal step counts as one iteration of the meter.
  void advanceTo(double sim_time);

  const FrequencyMeter& meter() const { return meter_; }
  /// Internal steps a fixed-step iteration runs: 1/rate_hz over the step size, at least one and
  /// at most the world's max iterations.
  std::uint64_t stepsPerIteration() const { return steps_per_iteration_; }
  /// Called each time a 1 s window completes (e.g. to print "Phx").
  std::function<void(const FrequencyMeter&)> on_window;

 private:
  void count();

  World& world_;
  LoopOptions options_;
  std::uint64_t steps_per_iteration_;
  Clock::duration period_;
  Clock::time_point next_tick_{};
  Clock::time_point start_{};
  bool started_ = false;
  FrequencyMeter meter_;
};

}  // namespace ambf_like
