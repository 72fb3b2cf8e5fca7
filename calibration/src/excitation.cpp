#include "calibration/excitation.hpp"

#include <cmath>

#include "raven/platform_profile.hpp"

namespace calibration {

namespace {

/// A zero-mean sine on one input, or nothing.
struct Wave {
  double amplitude = 0.0, frequency = 0.0, phase = 0.0;
  double at(double t) const { return amplitude * std::sin(2.0 * M_PI * frequency * t + phase); }
  /// As a trigger (0 .. 3.996 on the paper's scale; the jaws close as it rises): swinging 90 %
  /// of the way to either end about the middle, or released when the wave is off.
  double trigger(double t) const {
    return amplitude > 0.0 ? 2.0 + 1.99 * at(t) / amplitude * 0.9 : 0.0;
  }
};

Wave drawWave(std::mt19937_64& random, double on_probability) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Wave w;
  if (unit(random) >= on_probability) return w;
  w.amplitude = 0.4 + 0.6 * unit(random);
  w.frequency = 0.1 + 0.7 * unit(random);
  w.phase = 2.0 * M_PI * unit(random);
  return w;
}

enum class Scheme { M2, M1Left, M1Right };

}  // namespace

std::vector<recording::GamepadState> randomExcitation(std::mt19937_64& random,
                                                      const ExcitationOptions& options) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const auto rows = static_cast<std::size_t>(options.seconds / options.iteration);
  std::vector<recording::GamepadState> out;
  out.reserve(rows);
  while (out.size() < rows) {
    const double pick = unit(random);
    const Scheme scheme =
        pick < 0.5 ? Scheme::M2 : (pick < 0.75 ? Scheme::M1Left : Scheme::M1Right);
    const auto length =
        std::min(rows - out.size(),
                 static_cast<std::size_t>((4.0 + 6.0 * unit(random)) / options.iteration));
    // Sticks (x, y each side), triggers, and bumpers toggling the left stick's y to z.
    std::array<Wave, 6> waves;
    for (auto& w : waves) w = drawWave(random, 0.6);
    const double bumper_period = 1.0 + 3.0 * unit(random);
    const bool use_bumpers = unit(random) < 0.5;
    for (std::size_t k = 0; k < length; ++k) {
      const double t = static_cast<double>(k) * options.iteration;
      recording::GamepadState pad;
      if (k == 0) {  // level-triggered scheme selection on the segment's first row
        pad.back = scheme != Scheme::M1Right;
        pad.start = scheme != Scheme::M1Left;
      }
      pad.left_x = waves[0].at(t);
      pad.left_y = waves[1].at(t);
      pad.right_x = waves[2].at(t);
      pad.right_y = waves[3].at(t);
      pad.left_trigger = waves[4].trigger(t);
      pad.right_trigger = waves[5].trigger(t);
      const bool z = use_bumpers && std::fmod(t, 2.0 * bumper_period) >= bumper_period;
      pad.left_bumper = z;
      pad.right_bumper = z && scheme == Scheme::M2;
      out.push_back(pad);
    }
  }
  return out;
}

Candidate scoreCandidate(const ReplaySetup& setup, const twin::CalibrationProfile& profile,
                         const MechanicsInformation& prior,
                         std::vector<recording::GamepadState> inputs) {
  ReplaySetup s = setup;
  s.inputs = inputs;
  s.start.reset();
  profile.applyTo(s.twin);
  const recording::RsRecording rs = recordReplay(s);
  Candidate c;
  c.inputs = std::move(inputs);
  c.trace = analysis::actuatorTrace(rs);
  const raven::JointLimits limits = raven::builtinProfile("physical").limits;
  const raven::ArmJoints margin = 0.01 * (limits.high - limits.low);
  for (const auto& arm : c.trace.arms) {
    for (const recording::ArmSignals& row : arm) {
      const raven::ArmJoints& q = row.joints;
      if (((q - limits.low).array() < margin.array()).any() ||
          ((limits.high - q).array() < margin.array()).any()) {
        c.within_limits = false;
      }
    }
  }
  c.information = informationOf(profile.mechanics, c.trace);
  MechanicsInformation total = prior;
  total += c.information;
  c.log_det = total.logDet(profile.uncertainty);
  return c;
}

twin::ArmsMechanics expectedUncertainty(const MechanicsInformation& prior,
                                        const Candidate& candidate) {
  MechanicsInformation total = prior;
  total += candidate.information;
  return total.standardDeviations();
}

double meanReduction(const twin::ArmsMechanics& before, const twin::ArmsMechanics& after) {
  double sum = 0.0;
  int n = 0;
  for (std::size_t a = 0; a < 2; ++a) {
    const twin::MotorMechanics &b = before[a], &c = after[a];
    for (int j = 0; j < raven::kJointCount; ++j) {
      for (int v = 0; v < kMechanicsValues; ++v) {
        const double s0 = b.field(static_cast<std::size_t>(v))(j);
        if (s0 <= 0.0) continue;
        sum += 1.0 - c.field(static_cast<std::size_t>(v))(j) / s0;
        ++n;
      }
    }
  }
  return n > 0 ? sum / n : 0.0;
}

}  // namespace calibration
