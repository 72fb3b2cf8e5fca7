#include "analysis/actuator_signals.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "bridge/raven_state.hpp"

namespace analysis {

namespace {

constexpr double kRadiansPerDegree = M_PI / 180.0;

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
  ActuatorTrace trace;
  trace.name = rs.path.filename().string();
  const auto column = [&](const std::string& name, raven::Arm arm, int joint) {
    return rs.column(name + std::to_string(bridge::ravenStateIndex(arm, joint)));
  };
  for (raven::Arm arm : raven::kArms) {
    ArmTrace& t = trace.arms[static_cast<std::size_t>(raven::index(arm))];
    std::array<std::array<std::size_t, raven::kJointCount>, 7> c{};
    const char* names[7] = {"jpos", "jpos_d", "mpos", "mvel", "mpos_d", "Tau", "dac_vals"};
    for (std::size_t n = 0; n < 7; ++n) {
      for (int j = 0; j < raven::kJointCount; ++j)
        c[n][static_cast<std::size_t>(j)] = column(names[n], arm, j);
    }
    for (const auto& row : rs.rows) {
      std::array<raven::ArmJoints, 7> v;
      for (std::size_t n = 0; n < 7; ++n) {
        for (int j = 0; j < raven::kJointCount; ++j)
          v[n](j) = row[c[n][static_cast<std::size_t>(j)]];
      }
      // jpos_d is logged in degrees, its insertion in metres x 180/pi; motor angles in degrees.
      v[1] *= kRadiansPerDegree;
      t.joints.push_back(v[0]);
      t.joint_setpoint.push_back(v[1]);
      t.motor.push_back(v[2]);
      t.motor_velocity.push_back(v[3]);
      t.motor_setpoint.push_back(v[4] * kRadiansPerDegree);
      t.torque.push_back(v[5]);
      t.dac.push_back(v[6]);
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
