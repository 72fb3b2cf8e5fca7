#include "calibration/actuation_fit.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <nlopt.hpp>

#include "calibration/mechanics_information.hpp"
#include "calibration/setpoint_replay.hpp"

namespace calibration {

namespace {

using analysis::ActuatorSignal;

constexpr std::array<ActuatorSignal, 3> kFitted{
    ActuatorSignal::MotorPosition, ActuatorSignal::MotorVelocity, ActuatorSignal::Torque};

double toUnit(const MechanicsParameter& p, double v) {
  if (p.log_scale) return std::log(v / p.lower) / std::log(p.upper / p.lower);
  return (v - p.lower) / (p.upper - p.lower);
}

double fromUnit(const MechanicsParameter& p, double u) {
  if (p.log_scale) return p.lower * std::pow(p.upper / p.lower, u);
  return p.lower + u * (p.upper - p.lower);
}

}  // namespace

std::vector<MechanicsParameter> mechanicsParameters(int joint) {
  const bool big = joint <= raven::kInsertion;
  // In twin::MotorMechanics::kNames order. Where the jaws' faces meet and how they give: only
  // the pair's sums show, and each jaw's motor has its say in them.
  const std::vector<MechanicsParameter> all{
      {0, big ? 2e-5 : 1e-6, big ? 2e-3 : 2e-4, true},
      {1, 0.0, big ? 0.3 : 0.05, false},
      {2, 0.0, 0.8, false},
      {3, 0.0, big ? 0.02 : 0.002, false},
      {twin::MotorMechanics::kOffset, big ? -0.15 : -0.025, big ? 0.15 : 0.025, false},
      {twin::MotorMechanics::kFace, -0.05, 0.05, false},
      {twin::MotorMechanics::kFaceCompliance, 0.0, 2.0, false},
      {twin::MotorMechanics::kCableFriction, 0.0, 0.3, false},
      {twin::MotorMechanics::kCableTravel, 0.02, 5.0, true},
      {twin::MotorMechanics::kGravityError, -0.8, 0.8, false},
  };
  std::vector<MechanicsParameter> p;
  for (const auto& parameter : all) {
    if (motorHasValue(joint, static_cast<int>(parameter.field))) p.push_back(parameter);
  }
  return p;
}

twin::ArmsMechanics startingMechanics() {
  const twin::DriveTrain drive = twin::DriveTrain::raven2();
  twin::MotorMechanics m;
  // maxon rotor inertias (RE 40: 142 g cm^2, RE 30: 33.5 g cm^2) seen at the gearbox output per
  // motor radian: J * gearbox.
  for (int j = 0; j < raven::kJointCount; ++j) {
    m.inertia(j) = (j <= raven::kInsertion ? 1.42e-5 : 3.35e-6) * drive.gearbox(j);
  }
  // raven2_sim's motor friction on the motors; on the arm motors its link friction through the
  // transmission lies beyond the cables, taken up over a motor radian (the order of the travel
  // the robot's elbow turns through after a reversal before it slides: docs/actuation.md).
  m.coulomb << 0.04, 0.07, 0.05, 0.005, 0.005, 0.005, 0.005;
  for (int j = 0; j <= raven::kInsertion; ++j) {
    constexpr std::array<double, 3> kLinkFriction{0.505, 0.49, 0.53};
    m.cable_friction(j) =
        kLinkFriction[static_cast<std::size_t>(j)] * drive.gearbox(j) / drive.transmission(j);
    m.cable_travel(j) = 1.0;
  }
  m.viscous << 2.5e-3, 2.4e-3, 2.8e-3, 1e-4, 1e-4, 1e-4, 1e-4;
  return {m, m};
}

twin::ArmsMechanics broadUncertainty(const twin::ArmsMechanics& mechanics) {
  twin::ArmsMechanics sd;
  for (std::size_t a = 0; a < 2; ++a) {
    for (std::size_t k = 0; k < twin::MotorMechanics::kNames.size(); ++k) {
      sd[a].field(k) = 0.5 * mechanics[a].field(k).cwiseAbs();
    }
    sd[a].load_friction.setConstant(0.2);
    sd[a].offset = 0.5 * mechanics[a].coulomb;
    sd[a].gravity_error.setZero();
    sd[a].gravity_error.head<3>().setConstant(0.2);
  }
  return sd;
}

double MechanicsScore::total() const {
  return joint[0].sum() + joint[1].sum();
}

MechanicsScore scoreMechanics(const twin::ArmsMechanics& mechanics,
                              const std::vector<analysis::ActuatorTrace>& recordings,
                              const analysis::ActuatorFidelity& spread) {
  MechanicsScore score;
  for (const auto& recording : recordings) {
    const auto twin = replaySetpoints(recording, mechanics);
    for (ActuatorSignal s : kFitted) {
      const auto k = static_cast<std::size_t>(s);
      const auto d = analysis::meanAbsoluteDifference(twin, recording, s);
      for (std::size_t arm = 0; arm < 2; ++arm) {
        const raven::ArmJoints scale = spread.spread[k][arm].cwiseMax(1e-12);
        score.joint[arm] +=
            d[arm].cwiseQuotient(scale) / static_cast<double>(recordings.size() * kFitted.size());
      }
    }
  }
  return score;
}

namespace {

/// One motor's fit: which arm and joint, its parameters, what it is scored on.
struct MotorFit {
  ActuationFitResult& result;
  const std::vector<MechanicsParameter>& parameters;
  std::size_t arm;
  int joint;
  const std::vector<analysis::ActuatorTrace>& train;
  const analysis::ActuatorFidelity& spread;
};

/// The motor's values, the fitted ones from `unit` (their bounds' unit scale).
twin::ArmsMechanics withUnit(const MotorFit& f, const std::vector<double>& unit) {
  twin::ArmsMechanics m = f.result.mechanics;
  for (std::size_t i = 0; i < unit.size(); ++i) {
    m[f.arm].field(f.parameters[i].field)(f.joint) = fromUnit(f.parameters[i], unit[i]);
  }
  return m;
}

/// BOBYQA (COBYLA for one value) on the motor's values from `unit`, left at the best found;
/// its score there.
double optimiseMotor(MotorFit& f, std::vector<double>& unit, double initial_step, int evaluations) {
  const auto n = unit.size();
  auto objective = [](const std::vector<double>& x, std::vector<double>&, void* data) {
    auto& c = *static_cast<MotorFit*>(data);
    ++c.result.evaluations;
    const double score = scoreMechanics(withUnit(c, x), c.train, c.spread).joint[c.arm](c.joint);
    return std::isfinite(score) ? score : 1e9;
  };
  // BOBYQA's quadratic model needs two or more dimensions.
  nlopt::opt optimiser(n >= 2 ? nlopt::LN_BOBYQA : nlopt::LN_COBYLA, static_cast<unsigned>(n));
  optimiser.set_lower_bounds(std::vector<double>(n, 0.0));
  optimiser.set_upper_bounds(std::vector<double>(n, 1.0));
  optimiser.set_min_objective(objective, &f);
  optimiser.set_maxeval(evaluations);
  optimiser.set_xtol_rel(1e-3);
  optimiser.set_initial_step(initial_step);
  double best = 0.0;
  try {
    optimiser.optimize(unit, best);
  } catch (const nlopt::roundoff_limited&) {
    best = optimiser.last_optimum_value();
  }
  return best;
}

/// Where a motor's fit starts: its values now and, where it has a cable, the same friction
/// split other ways between the motor and the friction beyond its cable (all on the motor, a
/// third beyond, two thirds beyond). A local search does not cross from one split to another:
/// the cable's travel means nothing without its friction.
std::vector<std::vector<double>> startsOf(const MotorFit& f) {
  const twin::MotorMechanics& m = f.result.mechanics[f.arm];
  std::vector<double> now;
  for (const auto& p : f.parameters) now.push_back(toUnit(p, m.field(p.field)(f.joint)));
  std::vector<std::vector<double>> starts{now};
  const auto at = [&](std::size_t field) {
    for (std::size_t i = 0; i < f.parameters.size(); ++i) {
      if (f.parameters[i].field == field) return static_cast<int>(i);
    }
    return -1;
  };
  const int coulomb = at(1 /* coulomb */), cable = at(twin::MotorMechanics::kCableFriction);
  if (coulomb < 0 || cable < 0) return starts;
  const double total = m.coulomb(f.joint) + m.cable_friction(f.joint);
  for (const double beyond : {0.0, 1.0 / 3.0, 2.0 / 3.0}) {
    std::vector<double> s = now;
    s[static_cast<std::size_t>(coulomb)] =
        toUnit(f.parameters[static_cast<std::size_t>(coulomb)], (1.0 - beyond) * total);
    s[static_cast<std::size_t>(cable)] =
        toUnit(f.parameters[static_cast<std::size_t>(cable)], beyond * total);
    starts.push_back(s);
  }
  return starts;
}

}  // namespace

ActuationFitResult fitActuation(const std::vector<analysis::ActuatorTrace>& train,
                                const twin::ArmsMechanics& initial,
                                const ActuationFitOptions& options,
                                const std::function<void(const std::string&)>& progress) {
  analysis::ActuatorFidelity spread;
  if (options.same_motion) {
    spread = analysis::actuatorFidelity({train[0]}, train);
  } else {
    for (raven::Arm arm : raven::kArms) {
      const auto noise = quantisationNoise(arm);
      const auto a = raven::slot(arm);
      for (std::size_t k = 0; k < noise.size(); ++k) spread.spread[k][a] = noise[k];
    }
  }
  ActuationFitResult result{initial, {}, 0};
  for (int sweep = 0; sweep < options.sweeps; ++sweep) {
    for (raven::Arm arm : raven::kArms) {
      const auto a = raven::slot(arm);
      for (int joint = 0; joint < raven::kJointCount; ++joint) {
        std::vector<MechanicsParameter> parameters;
        for (const auto& p : mechanicsParameters(joint)) {
          if (options.fields.empty() || std::find(options.fields.begin(), options.fields.end(),
                                                  p.field) != options.fields.end()) {
            parameters.push_back(p);
          }
        }
        if (parameters.empty()) continue;
        MotorFit fit{result, parameters, a, joint, train, spread};
        // The first sweep tries every start; the later ones go on from the best.
        auto starts = startsOf(fit);
        if (sweep > 0) starts.resize(1);
        double best = INFINITY;
        std::vector<double> best_unit;
        for (auto& unit : starts) {
          for (double& u : unit) u = std::clamp(u, 0.0, 1.0);
          const double score =
              optimiseMotor(fit, unit, sweep == 0 ? 0.15 : 0.05, options.evaluations_per_joint);
          if (score < best) {
            best = score;
            best_unit = unit;
          }
        }
        result.mechanics = withUnit(fit, best_unit);
        if (progress) {
          progress(fmt::format("  sweep {} {} {}: score {:.3f}", sweep + 1, armName(arm),
                               raven::kJointNames[static_cast<std::size_t>(joint)], best));
        }
      }
    }
  }
  result.score = scoreMechanics(result.mechanics, train, spread);
  return result;
}

}  // namespace calibration
