#include "calibration/tracking_fit.hpp"

#include <cmath>
#include <nlopt.hpp>
#include <stdexcept>

namespace calibration {

namespace {

/// The drive groups and the joints (raven::ArmJoints order) each one sets.
const std::vector<std::pair<std::string, std::vector<int>>>& driveGroups() {
  static const std::vector<std::pair<std::string, std::vector<int>>> groups{
      {"shoulder", {raven::kShoulder}},
      {"elbow", {raven::kElbow}},
      {"insertion", {raven::kInsertion}},
      {"instrument", {raven::kRoll, raven::kWrist, raven::kJaw1, raven::kJaw2}}};
  return groups;
}

double fromUnit(const Parameter& p, double u) {
  return p.log_scale ? p.lower * std::pow(p.upper / p.lower, u) : p.lower + u * (p.upper - p.lower);
}

double toUnit(const Parameter& p, double v) {
  return p.log_scale ? std::log(v / p.lower) / std::log(p.upper / p.lower)
                     : (v - p.lower) / (p.upper - p.lower);
}

std::string stopReason(nlopt::result r) {
  switch (r) {
    case nlopt::SUCCESS:
      return "converged";
    case nlopt::FTOL_REACHED:
      return "score tolerance reached";
    case nlopt::XTOL_REACHED:
      return "parameter tolerance reached";
    case nlopt::MAXEVAL_REACHED:
      return "evaluation budget used";
    default:
      return "stopped (nlopt code " + std::to_string(static_cast<int>(r)) + ")";
  }
}

}  // namespace

const std::vector<Parameter>& trackingParameters() {
  static const std::vector<Parameter> parameters = [] {
    std::vector<Parameter> list{{"latency_cycles", 0.0, 40.0, 2.0, false}};
    for (const auto& [name, joints] : driveGroups()) {
      list.push_back({name + " bandwidth_hz", 0.5, 200.0, 20.0, true});
      list.push_back({name + " damping_ratio", 0.2, 4.0, 1.0, true});
      const double deadband = name == "insertion" ? 0.002 : 0.02;  // m, rad
      list.push_back({name + " friction_deadband", 0.0, deadband, 0.0, false});
    }
    return list;
  }();
  return parameters;
}

twin::TrackingParams toTracking(const std::vector<double>& values) {
  if (values.size() != trackingParameters().size()) {
    throw std::invalid_argument("toTracking: expected " +
                                std::to_string(trackingParameters().size()) + " values");
  }
  twin::TrackingParams t;
  t.latency_cycles = values[0];
  std::size_t next = 1;
  for (const auto& [name, joints] : driveGroups()) {
    for (int j : joints) {
      t.bandwidth_hz(j) = values[next];
      t.damping_ratio(j) = values[next + 1];
      t.friction_deadband(j) = values[next + 2];
    }
    next += 3;
  }
  return t;
}

double fidelityScore(const Figures& twin_vs_physical, const Figures& scale) {
  const auto f = twin_vs_physical.values();
  const auto s = scale.values();
  double sum = 0.0;
  for (std::size_t i = 0; i < f.size(); ++i) sum += f[i] / s[i];
  return sum / static_cast<double>(f.size());
}

FitResult fitTracking(const ReplaySetup& setup, const analysis::PlatformTrials& train,
                      const Figures& scale, const FitOptions& options,
                      const std::function<void(int, double)>& progress) {
  const auto& parameters = trackingParameters();
  const auto n = parameters.size();
  auto values = [&](const std::vector<double>& unit) {
    std::vector<double> v(n);
    for (std::size_t i = 0; i < n; ++i) v[i] = fromUnit(parameters[i], unit[i]);
    return v;
  };
  struct Context {
    const ReplaySetup& setup;
    const analysis::PlatformTrials& train;
    const Figures& scale;
    const std::function<std::vector<double>(const std::vector<double>&)> values;
    const std::function<void(int, double)>& progress;
    int evaluations = 0;
  } context{setup, train, scale, values, progress};
  auto objective = [](const std::vector<double>& unit, std::vector<double>&, void* data) {
    auto& c = *static_cast<Context*>(data);
    const auto trial = replayOnTwin(c.setup, toTracking(c.values(unit)));
    const double score = fidelityScore(twinVsPhysical(trial, c.train), c.scale);
    ++c.evaluations;
    if (c.progress) c.progress(c.evaluations, score);
    return std::isfinite(score) ? score : 1e9;
  };

  nlopt::opt optimiser(nlopt::LN_BOBYQA, static_cast<unsigned>(n));
  optimiser.set_lower_bounds(std::vector<double>(n, 0.0));
  optimiser.set_upper_bounds(std::vector<double>(n, 1.0));
  optimiser.set_min_objective(objective, &context);
  optimiser.set_maxeval(options.max_evaluations);
  optimiser.set_xtol_rel(options.tolerance);
  optimiser.set_initial_step(0.15);
  std::vector<double> unit(n);
  for (std::size_t i = 0; i < n; ++i) unit[i] = toUnit(parameters[i], parameters[i].initial);
  FitResult result;
  nlopt::result code = nlopt::FAILURE;
  try {
    code = optimiser.optimize(unit, result.score);
  } catch (const nlopt::roundoff_limited&) {
    code = nlopt::ROUNDOFF_LIMITED;
    result.score = optimiser.last_optimum_value();
  }
  result.values = values(unit);
  result.tracking = toTracking(result.values);
  result.evaluations = context.evaluations;
  result.stop_reason = stopReason(code);
  return result;
}

}  // namespace calibration
