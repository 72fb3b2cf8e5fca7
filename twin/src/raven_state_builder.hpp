#pragma once
// Fills a raven_state sample the way the robot's firmware does, from a twin's state.

#include "bridge/raven_state.hpp"
#include "twin/actuation.hpp"
#include "twin/raven_core.hpp"
#include "twin/vocabulary.hpp"

namespace twin {

/// What the sample is built from: the core, this cycle's readings and last cycle's positions
/// (for the tool velocities in jac_vel).
struct TwinStateSources {
  const RavenCore& core;
  const raven::PerArm<ActuatorReadings>& readings;
  const ArmPair& previous_position;
};

/// Every field the twin can know; encoffsets and jac_f stay 0 (the twin's encoders read from
/// zero; upstream fills jac_f with velocities by mistake).
RavenStateSnapshot makeRavenState(const TwinStateSources& sources);

/// The runlevel and sublevel the robot reports in an operating state.
std::pair<std::int32_t, std::int32_t> runlevelOf(const OperatingStatus& status);

}  // namespace twin
