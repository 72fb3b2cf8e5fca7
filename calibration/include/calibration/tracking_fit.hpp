#pragma once
// Fits the twin's tracking response (twin::TrackingParams) to physical replays of the same
// inputs: a derivative-free bounded optimiser (NLopt's BOBYQA) minimises the twin's j_P and j_V
// figures against the physical trials, each relative to the robot's own repeatability.

#include <functional>
#include <string>
#include <vector>

#include "calibration/fidelity.hpp"
#include "calibration/twin_replay.hpp"
#include "twin/tracking_response.hpp"

namespace calibration {

/// One fitted quantity: its name, bounds and whether it is searched on a log scale.
struct Parameter {
  std::string name;
  double lower = 0.0, upper = 1.0, initial = 0.5;
  bool log_scale = false;
};

/// The response's fitted parameters: the latency, and a natural frequency, damping ratio and
/// friction deadband for each drive group (shoulder, elbow, insertion, and the instrument's four
/// cable-driven joints, which share motors of one kind and are not all exercised by every
/// recording).
const std::vector<Parameter>& trackingParameters();
/// Parameter values (in trackingParameters() order) as a tracking response.
twin::TrackingParams toTracking(const std::vector<double>& values);

/// The fit's objective: the mean over the four summary figures of twin-vs-physical over the
/// robot's own T_PP (with one physical trial, over `scale`'s figures instead).
double fidelityScore(const Figures& twin_vs_physical, const Figures& scale);

struct FitOptions {
  int max_evaluations = 200;
  double tolerance = 1e-3;  ///< relative, on the normalised parameters
};

struct FitResult {
  std::vector<double> values;  ///< in trackingParameters() order
  twin::TrackingParams tracking;
  double score = 0.0;
  int evaluations = 0;
  std::string stop_reason;
};

/// Fits to `train`: each evaluation replays the inputs on a twin with the candidate response.
/// `progress` (if set) is called after each evaluation with its number and score.
FitResult fitTracking(const ReplaySetup& setup, const analysis::PlatformTrials& train,
                      const Figures& scale, const FitOptions& options,
                      const std::function<void(int, double)>& progress = {});

}  // namespace calibration
