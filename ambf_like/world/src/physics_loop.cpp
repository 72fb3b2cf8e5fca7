#include "ambf_like/physics_loop.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <thread>

namespace ambf_like {

PhysicsLoop::PhysicsLoop(World& world, LoopOptions options) : world_(world), options_(options) {
  if (!(options_.rate_hz > 0.0) || !std::isfinite(options_.rate_hz)) {
    throw std::invalid_argument("loop rate must be a positive number of Hz");
  }
  // As AMBF's Bullet does with its maxSubSteps: an iteration runs at most the world's max
  // iterations of internal steps, and simulated time falls behind a loop slower than that
  // (a rate of 1e-9 Hz would otherwise ask for 1e12 steps at once).
  const double per_iteration = 1.0 / options_.rate_hz / world_.stepSize();
  const auto most = static_cast<double>(world_.settings().max_iterations);
  steps_per_iteration_ =
      static_cast<std::uint64_t>(std::clamp(std::round(per_iteration), 1.0, most));
  period_ = std::chrono::duration_cast<Clock::duration>(
      std::chrono::duration<double>(1.0 / options_.rate_hz));
}

void PhysicsLoop::count() {
  if (meter_.tick() && on_window) on_window(meter_);
}

void PhysicsLoop::iterate() {
  const auto now = Clock::now();
  if (!started_) {
    started_ = true;
    start_ = now;
    next_tick_ = now;
  }
  if (options_.paced) {
    next_tick_ += period_;
    if (next_tick_ < now) {
      next_tick_ = now;  // fell behind: do not burst to catch up
    } else {
      std::this_thread::sleep_until(next_tick_);
    }
  }
  std::uint64_t steps = steps_per_iteration_;
  if (!options_.fixed_time_step) {
    const double wall = std::chrono::duration<double>(Clock::now() - start_).count();
    const double behind = std::floor((wall - world_.time()) / world_.stepSize());
    steps = static_cast<std::uint64_t>(
        std::clamp(behind, 0.0, static_cast<double>(world_.settings().max_iterations)));
  }
  world_.step(steps);
  count();
}

void PhysicsLoop::advanceTo(double sim_time) {
  const double half_step = world_.stepSize() / 2.0;
  while (world_.time() + half_step < sim_time) {
    world_.step();
    count();
  }
}

}  // namespace ambf_like
