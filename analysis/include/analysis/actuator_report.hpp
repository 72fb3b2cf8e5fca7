#pragma once
// The disparity report below the joints: for every platform whose recordings log actuator
// signals (mpos, mvel, Tau, dac_vals; AMBF's do not), the same comparisons as the joints' (T_PP,
// T_SS, T_PS over every trial pair), per signal and joint, and each simulation's figures over the
// robot's own. Rows are aligned by index whatever the joints' alignment.

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "analysis/actuator_signals.hpp"
#include "analysis/trial_set.hpp"

namespace analysis {

/// One platform's actuator traces, its trials' (empty: its recordings log none).
struct PlatformActuators {
  const PlatformTrials* platform = nullptr;
  std::vector<const ActuatorTrace*> traces;
};

/// Every platform of `set`, with its trials' traces when every one of them logs them.
std::vector<PlatformActuators> actuatorPlatforms(const TrialSet& set);

/// One comparison: per signal (kActuatorSignals order), arm and joint, the mean over trial pairs
/// of mean |a - b| in the logged unit.
struct ActuatorComparison {
  std::string symbol;       ///< T_PP, T_SS, T_PS
  std::string description;  ///< "twin vs physical"
  std::array<raven::PerArm<raven::ArmJoints>, 4> mean_abs;
  /// Over the physical platform's T_PP (when it has two or more trials): per signal, the median
  /// over the joints the robot moves.
  std::optional<std::array<double, 4>> median_over_robot;
};

/// Every platform with two or more traces against itself, then every pair of platforms with
/// traces (physical first when one of them is).
std::vector<ActuatorComparison> compareActuators(const std::vector<PlatformActuators>& platforms);

/// actuators.json (every comparison), actuators.csv (per comparison, signal and joint) and
/// actuator_trajectories.csv (per platform, signal, joint and row: the mean across trials) in
/// `dir`. Throws std::runtime_error naming a file it cannot write.
void writeActuatorReport(const std::vector<PlatformActuators>& platforms,
                         const std::vector<ActuatorComparison>& comparisons,
                         const std::filesystem::path& dir);

}  // namespace analysis
