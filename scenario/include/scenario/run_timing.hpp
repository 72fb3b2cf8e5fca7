#pragma once
// How long a scripted run took on both clocks, and the rates that follow from it.

#include <cstdint>
#include <nlohmann/json.hpp>

namespace scenario {

/// A run's clocks: simulated seconds, wall seconds, physics steps.
struct RunTiming {
  double sim_time = 0.0;      ///< simulated seconds, homing included
  double wall_time = 0.0;     ///< seconds on the wall clock, building the scene included
  double loop_seconds = 0.0;  ///< wall seconds spent stepping (after building)
  std::uint64_t steps = 0;    ///< physics steps

  /// Simulated over wall seconds of the loop (> 1: faster than real time).
  double realTimeFactor() const { return loop_seconds > 0.0 ? sim_time / loop_seconds : 0.0; }
  /// Physics steps per wall second of the loop: the dynamic loop frequency (AMBF's "Phx").
  double loopFrequency() const {
    return loop_seconds > 0.0 ? static_cast<double>(steps) / loop_seconds : 0.0;
  }
  /// The timing fields of a result's JSON object.
  void addTo(nlohmann::json& j) const {
    j["sim_time_s"] = sim_time;
    j["wall_time_s"] = wall_time;
    j["loop_time_s"] = loop_seconds;
    j["real_time_factor"] = realTimeFactor();
    j["loop_frequency_hz"] = loopFrequency();
    j["steps"] = steps;
  }
  /// Reads back what addTo wrote (nlohmann::json::exception naming the field if one is missing).
  static RunTiming fromJson(const nlohmann::json& j) {
    return {j.at("sim_time_s").get<double>(), j.at("wall_time_s").get<double>(),
            j.at("loop_time_s").get<double>(), j.at("steps").get<std::uint64_t>()};
  }
};

}  // namespace scenario
