#include "analysis/actuator_signals.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace analysis {

namespace {

const std::vector<raven::ArmJoints>& select(const ArmTrace& t, ActuatorSignal s) {
  switch (s) {
    case ActuatorSignal::MotorPosition:
      return t.motor;
    case ActuatorSignal::MotorVelocity:
      return t.motor_velocity;
    case ActuatorSignal::Torque:
      return t.torque;
    case ActuatorSignal::Dac:
      break;
  }
  return t.dac;
}

}  // namespace

const char* columnName(ActuatorSignal s) {
  switch (s) {
    case ActuatorSignal::MotorPosition:
      return "mpos";
    case ActuatorSignal::MotorVelocity:
      return "mvel";
    case ActuatorSignal::Torque:
      return "Tau";
    case ActuatorSignal::Dac:
      break;
  }
  return "dac_vals";
}

const char* loggedUnit(ActuatorSignal s) {
  switch (s) {
    case ActuatorSignal::MotorPosition:
      return "deg";
    case ActuatorSignal::MotorVelocity:
      return "deg/s";
    case ActuatorSignal::Torque:
      return "N m";
    case ActuatorSignal::Dac:
      break;
  }
  return "counts";
}

const std::vector<raven::ArmJoints>& ArmTrace::of(ActuatorSignal s) const {
  return select(*this, s);
}

ActuatorTrace actuatorTrace(const recording::RsRecording& rs) {
  constexpr double kDegreesPerRadian = 180.0 / M_PI;
  ActuatorTrace trace;
  trace.name = rs.path.filename().string();
  for (raven::Arm arm : raven::kArms) {
    ArmTrace& t = trace.arms[static_cast<std::size_t>(raven::index(arm))];
    for (std::size_t r = 0; r < rs.rows.size(); ++r) {
      const recording::ArmSignals s = rs.signals(r, arm);
      t.joints.push_back(s.joints);
      t.joint_setpoint.push_back(s.joint_setpoint);
      t.motor.push_back(s.motor * kDegreesPerRadian);  // compared as logged
      t.motor_velocity.push_back(s.motor_velocity * kDegreesPerRadian);
      t.motor_setpoint.push_back(s.motor_setpoint);
      t.torque.push_back(s.torque);
      t.dac.push_back(s.dac);
    }
  }
  const double t0 = rs.rows.empty() ? 0.0 : rs.time(0);
  for (std::size_t r = 0; r < rs.rows.size(); ++r) trace.time.push_back(rs.time(r) - t0);
  return trace;
}

std::array<raven::ArmJoints, 2> meanAbsoluteDifference(const ActuatorTrace& a,
                                                       const ActuatorTrace& b, ActuatorSignal s) {
  std::array<raven::ArmJoints, 2> out{};
  const std::size_t rows = std::min(a.rows(), b.rows());
  for (std::size_t arm = 0; arm < 2; ++arm) {
    const auto& x = a.arms[arm].of(s);
    const auto& y = b.arms[arm].of(s);
    raven::ArmJoints sum = raven::ArmJoints::Zero();
    for (std::size_t r = 0; r < rows; ++r) sum += (x[r] - y[r]).cwiseAbs();
    out[arm] = rows > 0 ? raven::ArmJoints(sum / static_cast<double>(rows)) : sum;
  }
  return out;
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
    std::vector<double> ratios;
    for (std::size_t arm = 0; arm < 2; ++arm) {
      f.spread[k][arm] /= static_cast<double>(pairs);
      for (int j = 0; j < raven::kJointCount; ++j) {
        if (f.spread[k][arm](j) > 0.0) ratios.push_back(f.twin[k][arm](j) / f.spread[k][arm](j));
      }
    }
    if (ratios.empty()) continue;
    std::sort(ratios.begin(), ratios.end());
    const std::size_t n = ratios.size();
    f.median_ratio[k] = n % 2 ? ratios[n / 2] : 0.5 * (ratios[n / 2 - 1] + ratios[n / 2]);
  }
  return f;
}

}  // namespace analysis
