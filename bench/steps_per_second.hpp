#pragma once
// Steps of a world per wall second: the loop frequency every section reports.

#include <chrono>

#include "ambf_like/world.hpp"

namespace bench {

/// Steps per wall second of `world` over `steps` steps, `each` run before every step.
template <typename Each>
double stepsPerSecond(ambf_like::World& world, int steps, Each each) {
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < steps; ++i) {
    each(i);
    world.step();
  }
  const std::chrono::duration<double> wall = std::chrono::steady_clock::now() - start;
  return steps / wall.count();
}

}  // namespace bench
