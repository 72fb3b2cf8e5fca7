#pragma once
// Where each quantity sits in PegTransferEnv's 72-value observation: the one definition, used by
// observe() and exported to Python (raven_sim.observation_layout()).

#include <array>
#include <cstddef>

#include "raven/arm.hpp"

namespace scenario::observation {

/// A run of values in the observation: [start, start + size).
struct Slice {
  int start = 0;
  int size = 0;
  constexpr int end() const { return start + size; }
};

/// One named part of the observation, and how many values each of its items has (an arm's, or
/// a ring's).
struct Part {
  const char* name;
  Slice slice;
  int item_size;
};

/// Measured joints, 7 per arm (left first): measured_js.
inline constexpr Part kJoints{"joints", {0, 14}, 7};
/// The commanded joint targets, 7 per arm.
inline constexpr Part kTargets{"targets", {14, 14}, 7};
/// Each arm's tool pose: x, y, z (m) and the quaternion w, x, y, z (measured_cp).
inline constexpr Part kToolPoses{"tool_poses", {28, 14}, 7};
/// Each arm's grasp force (3, N) and torque (3, N m) (measured_cf).
inline constexpr Part kWrenches{"wrenches", {42, 12}, 6};
/// Each ring's centre (x, y, z, m), ring1..ring6.
inline constexpr Part kRings{"rings", {54, 18}, 3};

/// Every part, in order; they tile the observation.
inline constexpr std::array<Part, 5> kParts{kJoints, kTargets, kToolPoses, kWrenches, kRings};
inline constexpr int kSize = kRings.slice.end();

/// Item `i` of `part` (an arm's slot, or a ring's index).
constexpr Slice item(const Part& part, std::size_t i) {
  return {part.slice.start + part.item_size * static_cast<int>(i), part.item_size};
}
/// `arm`'s values of a per-arm part.
constexpr Slice of(const Part& part, raven::Arm arm) {
  return item(part, raven::slot(arm));
}

}  // namespace scenario::observation
