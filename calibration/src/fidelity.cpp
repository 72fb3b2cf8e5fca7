#include "calibration/fidelity.hpp"

#include "analysis/metrics.hpp"

namespace calibration {

namespace {

Figures figuresOf(const analysis::Comparison& c, bool remove_first_row) {
  using analysis::Quantity;
  const auto revolute = analysis::revoluteJoints();
  const auto insertion = analysis::prismaticJoints();
  return {analysis::groupFigure(c, revolute, Quantity::Position, remove_first_row),
          analysis::groupFigure(c, insertion, Quantity::Position, remove_first_row),
          analysis::groupFigure(c, revolute, Quantity::Velocity, remove_first_row),
          analysis::groupFigure(c, insertion, Quantity::Velocity, remove_first_row)};
}

JointFigures jointsOf(const analysis::Comparison& c) {
  JointFigures f;
  for (const auto& joint : analysis::recordedJoints()) {
    const double scale = joint.unit == "m" ? 1000.0 : 1.0;
    f.position.push_back(
        scale *
        analysis::jointStats(c, analysis::Quantity::Position, joint.column, false).mean_abs);
    f.velocity.push_back(
        scale *
        analysis::jointStats(c, analysis::Quantity::Velocity, joint.column, false).mean_abs);
  }
  return f;
}

analysis::PlatformTrials twinTrials(const analysis::Trial& twin) {
  analysis::PlatformTrials t;
  t.profile.name = "twin";
  t.profile.role = analysis::Role::Simulation;
  t.trials = {twin};
  return t;
}

}  // namespace

const std::array<std::string, 4>& Figures::names() {
  static const std::array<std::string, 4> names{"revolute j_P (rad)", "insertion j_P (mm)",
                                                "revolute j_V (rad/s)", "insertion j_V (mm/s)"};
  return names;
}

analysis::PlatformTrials physicalTrials(std::vector<analysis::Trial> trials) {
  analysis::PlatformTrials p;
  p.profile.name = "physical";
  p.profile.role = analysis::Role::Physical;
  p.trials = std::move(trials);
  return p;
}

Figures twinVsPhysical(const analysis::Trial& twin, const analysis::PlatformTrials& physical,
                       bool remove_first_row) {
  const auto twin_trials = twinTrials(twin);
  return figuresOf({&twin_trials, &physical}, remove_first_row);
}

Figures robotRepeatability(const analysis::PlatformTrials& physical, bool remove_first_row) {
  return figuresOf({&physical, &physical}, remove_first_row);
}

JointFigures jointsTwinVsPhysical(const analysis::Trial& twin,
                                  const analysis::PlatformTrials& physical) {
  const auto twin_trials = twinTrials(twin);
  return jointsOf({&twin_trials, &physical});
}

JointFigures jointsRepeatability(const analysis::PlatformTrials& physical) {
  return jointsOf({&physical, &physical});
}

}  // namespace calibration
