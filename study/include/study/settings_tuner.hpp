#pragma once
// Tuning a participant's mapping between trials by Bayesian optimisation: a Gaussian process
// (squared-exponential kernel, its length scale and noise chosen by marginal likelihood) over
// the settings the protocol lets move, scaled to the unit box; the first trials spread over the
// box (a Halton sequence), then each next trial takes the settings of largest expected
// improvement of the stated cost. Deterministic: the same history proposes the same settings.

#include <vector>

#include "study/protocol.hpp"

namespace study {

/// One tuning trial: the settings tried and the cost measured.
struct TuningObservation {
  std::vector<double> settings;  ///< in TuningSpec::parameters order, the protocol's units
  double cost = 0.0;
};

/// The tuner's advice after some trials.
struct Recommendation {
  std::vector<double> settings;
  double predicted_cost = 0.0;  ///< the process's mean there
};

/// Proposes and recommends settings within the protocol's bounds.
class SettingsTuner {
 public:
  SettingsTuner(std::vector<TunedParameter> parameters, int initial);

  /// The settings for the next trial after `history`.
  std::vector<double> propose(const std::vector<TuningObservation>& history) const;
  /// Among the settings tried, those the process predicts cheapest (noise averaged out).
  /// Throws std::invalid_argument on an empty history.
  Recommendation recommend(const std::vector<TuningObservation>& history) const;

 private:
  std::vector<double> fromBox(const std::vector<double>& unit) const;

  std::vector<TunedParameter> parameters_;
  int initial_;
};

}  // namespace study
