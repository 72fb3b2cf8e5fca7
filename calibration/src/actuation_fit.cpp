#include "calibration/actuation_fit.hpp"

#include <fmt/format.h>

#include <algorithm>
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
  // raven2_sim's motor friction plus its link friction through the transmission.
  m.coulomb << 0.04 + 0.505 * drive.gearbox(0) / drive.transmission(0),
      0.07 + 0.49 * drive.gearbox(1) / drive.transmission(1),
      0.05 + 0.53 * drive.gearbox(2) / drive.transmission(2), 0.005, 0.005, 0.005, 0.005;
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
        const auto n = parameters.size();
        if (n == 0) continue;
        struct Context {
          ActuationFitResult& result;
          const std::vector<MechanicsParameter>& parameters;
          std::size_t arm;
          int joint;
          const std::vector<analysis::ActuatorTrace>& train;
          const analysis::ActuatorFidelity& spread;
        } context{result, parameters, a, joint, train, spread};
        auto objective = [](const std::vector<double>& unit, std::vector<double>&, void* data) {
          auto& c = *static_cast<Context*>(data);
          twin::ArmsMechanics m = c.result.mechanics;
          for (std::size_t i = 0; i < unit.size(); ++i) {
            m[c.arm].field(c.parameters[i].field)(c.joint) = fromUnit(c.parameters[i], unit[i]);
          }
          ++c.result.evaluations;
          const double score = scoreMechanics(m, c.train, c.spread).joint[c.arm](c.joint);
          return std::isfinite(score) ? score : 1e9;
        };
        // BOBYQA's quadratic model needs two or more dimensions.
        nlopt::opt optimiser(n >= 2 ? nlopt::LN_BOBYQA : nlopt::LN_COBYLA,
                             static_cast<unsigned>(n));
        optimiser.set_lower_bounds(std::vector<double>(n, 0.0));
        optimiser.set_upper_bounds(std::vector<double>(n, 1.0));
        optimiser.set_min_objective(objective, &context);
        optimiser.set_maxeval(options.evaluations_per_joint);
        optimiser.set_xtol_rel(1e-3);
        optimiser.set_initial_step(sweep == 0 ? 0.15 : 0.05);
        std::vector<double> unit(n);
        for (std::size_t i = 0; i < n; ++i) {
          unit[i] = std::clamp(
              toUnit(parameters[i], result.mechanics[a].field(parameters[i].field)(joint)), 0.0,
              1.0);
        }
        double best = 0.0;
        try {
          optimiser.optimize(unit, best);
        } catch (const nlopt::roundoff_limited&) {
          best = optimiser.last_optimum_value();
        }
        for (std::size_t i = 0; i < n; ++i) {
          result.mechanics[a].field(parameters[i].field)(joint) = fromUnit(parameters[i], unit[i]);
        }
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
