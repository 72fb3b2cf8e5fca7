#include "analysis/actuator_signals.hpp"

#include <cmath>
#include <stdexcept>

#include "analysis/metrics.hpp"

namespace analysis {

namespace {

/// Where each signal sits in a row, its recorder column and its logged unit.
struct SignalColumn {
  const char* name;
  const char* unit;
  raven::ArmJoints recording::ArmSignals::*field;
  double to_logged;  ///< SI -> logged unit
};
constexpr double kDegreesPerRadian = 180.0 / M_PI;
constexpr std::array<SignalColumn, 4> kColumns{{
    {"mpos", "deg", &recording::ArmSignals::motor, kDegreesPerRadian},
    {"mvel", "deg/s", &recording::ArmSignals::motor_velocity, kDegreesPerRadian},
    {"Tau", "N m", &recording::ArmSignals::torque, 1.0},
    {"dac_vals", "counts", &recording::ArmSignals::dac, 1.0},
}};

const SignalColumn& columnOf(ActuatorSignal s) {
  return kColumns[static_cast<std::size_t>(s)];
}

}  // namespace

const char* columnName(ActuatorSignal s) {
  return columnOf(s).name;
}

const char* loggedUnit(ActuatorSignal s) {
  return columnOf(s).unit;
}

raven::ArmJoints logged(const recording::ArmSignals& row, ActuatorSignal s) {
  const SignalColumn& c = columnOf(s);
  return row.*c.field * c.to_logged;
}

ActuatorTrace actuatorTrace(const recording::RsRecording& rs) {
  ActuatorTrace trace;
  trace.name = rs.path.filename().string();
  for (raven::Arm arm : raven::kArms) {
    auto& rows = trace.arms[raven::slot(arm)];
    for (std::size_t r = 0; r < rs.rows.size(); ++r) rows.push_back(rs.signals(r, arm));
  }
  const double t0 = rs.rows.empty() ? 0.0 : rs.time(0);
  for (std::size_t r = 0; r < rs.rows.size(); ++r) trace.time.push_back(rs.time(r) - t0);
  return trace;
}

std::optional<ActuatorTrace> loggedActuatorTrace(const recording::RsRecording& rs) {
  ActuatorTrace trace;
  try {
    trace = actuatorTrace(rs);
  } catch (const recording::RecordingError&) {
    return std::nullopt;  // a column is missing: an older or foreign layout
  }
  bool moving = false;
  for (const auto& arm : trace.arms) {
    for (const recording::ArmSignals& s : arm) {
      for (const raven::ArmJoints* v : {&s.joints, &s.joint_setpoint, &s.motor, &s.motor_velocity,
                                        &s.motor_setpoint, &s.torque, &s.dac}) {
        if (!v->allFinite()) return std::nullopt;
      }
      moving = moving || !s.motor.isZero();
    }
  }
  if (!moving) return std::nullopt;
  return trace;
}

SignalJoints zeroSignals() {
  SignalJoints z;
  for (auto& signal : z) signal.fill(raven::ArmJoints::Zero());
  return z;
}

raven::PerArm<raven::ArmJoints> meanAbsoluteDifference(const ActuatorTrace& a,
                                                       const ActuatorTrace& b, ActuatorSignal s) {
  raven::PerArm<raven::ArmJoints> out{};
  const std::size_t rows = std::min(a.rows(), b.rows());
  const SignalColumn& c = columnOf(s);
  for (std::size_t arm = 0; arm < 2; ++arm) {
    raven::ArmJoints sum = raven::ArmJoints::Zero();
    for (std::size_t r = 0; r < rows; ++r) {
      sum += (a.arms[arm][r].*c.field - b.arms[arm][r].*c.field).cwiseAbs();
    }
    out[arm] = rows > 0 ? raven::ArmJoints(sum * c.to_logged / static_cast<double>(rows)) : sum;
  }
  return out;
}

double medianRatio(const raven::PerArm<raven::ArmJoints>& value,
                   const raven::PerArm<raven::ArmJoints>& spread) {
  std::vector<double> ratios;
  for (std::size_t arm = 0; arm < 2; ++arm) {
    for (int j = 0; j < raven::kJointCount; ++j) {
      if (spread[arm](j) > 0.0) ratios.push_back(value[arm](j) / spread[arm](j));
    }
  }
  return ratios.empty() ? 0.0 : median(std::move(ratios));
}

ActuatorFidelity actuatorFidelity(const std::vector<ActuatorTrace>& twin,
                                  const std::vector<ActuatorTrace>& physical,
                                  const std::vector<ActuatorTrace>& spread_from) {
  const auto& robot = spread_from.empty() ? physical : spread_from;
  if (robot.size() < 2) throw std::invalid_argument("the robot's spread needs two physical trials");
  if (physical.empty() || (twin.size() != 1 && twin.size() != physical.size())) {
    throw std::invalid_argument("one twin trace, or one per physical trial");
  }
  ActuatorFidelity f;
  for (std::size_t k = 0; k < kActuatorSignals.size(); ++k) {
    const ActuatorSignal s = kActuatorSignals[k];
    for (std::size_t i = 0; i < physical.size(); ++i) {
      const auto d = meanAbsoluteDifference(twin[twin.size() == 1 ? 0 : i], physical[i], s);
      for (std::size_t arm = 0; arm < 2; ++arm) {
        f.twin[k][arm] += d[arm] / static_cast<double>(physical.size());
      }
    }
    std::size_t pairs = 0;
    for (std::size_t i = 0; i < robot.size(); ++i) {
      for (std::size_t j = i + 1; j < robot.size(); ++j, ++pairs) {
        const auto p = meanAbsoluteDifference(robot[i], robot[j], s);
        for (std::size_t arm = 0; arm < 2; ++arm) f.spread[k][arm] += p[arm];
      }
    }
    for (std::size_t arm = 0; arm < 2; ++arm) f.spread[k][arm] /= static_cast<double>(pairs);
    f.median_ratio[k] = medianRatio(f.twin[k], f.spread[k]);
  }
  return f;
}

}  // namespace analysis
