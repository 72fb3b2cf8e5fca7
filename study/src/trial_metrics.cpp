#include "study/trial_metrics.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <unsupported/Eigen/FFT>

#include "not_measured.hpp"
#include "raven/arm_kinematics.hpp"
#include "raven/platform_profile.hpp"
#include "recording/cf_recording.hpp"
#include "recording/recording_io.hpp"
#include "study/instrument_metrics.hpp"
#include "study/trial_events.hpp"

namespace study {

namespace {

namespace fs = std::filesystem;
constexpr double kIdleSpeed = 0.001;  ///< m/s: both tips slower than this count as idle
constexpr double kSampleRate = 50.0;  ///< Hz: speed profiles resampled for SPARC

fs::path fileEnding(const fs::path& dir, const std::string& ending) {
  if (fs::is_directory(dir)) {
    for (const auto& entry : fs::directory_iterator(dir)) {
      const std::string name = entry.path().filename().string();
      if (name.size() >= ending.size() &&
          name.compare(name.size() - ending.size(), ending.size(), ending) == 0) {
        return entry.path();
      }
    }
  }
  throw recording::RecordingError(dir.string() + ": no *" + ending + " file in the trial");
}

/// One arm's tool-tip path: times and positions (controller frame).
struct TipPath {
  std::vector<double> t;
  std::vector<Eigen::Vector3d> p;

  double length(double from, double to) const {
    double sum = 0.0;
    for (std::size_t i = 1; i < t.size(); ++i) {
      if (t[i - 1] >= from && t[i] <= to) sum += (p[i] - p[i - 1]).norm();
    }
    return sum;
  }
  /// The speed between `from` and `to`, resampled at kSampleRate.
  std::vector<double> speed(double from, double to) const {
    std::vector<double> mid_t, v;
    for (std::size_t i = 1; i < t.size(); ++i) {
      const double dt = t[i] - t[i - 1];
      if (dt <= 0.0) continue;
      mid_t.push_back(0.5 * (t[i] + t[i - 1]));
      v.push_back((p[i] - p[i - 1]).norm() / dt);
    }
    std::vector<double> out;
    for (double s = from; s <= to && !mid_t.empty(); s += 1.0 / kSampleRate) {
      const auto it = std::lower_bound(mid_t.begin(), mid_t.end(), s);
      if (it == mid_t.begin()) {
        out.push_back(v.front());
      } else if (it == mid_t.end()) {
        out.push_back(v.back());
      } else {
        const std::size_t k = static_cast<std::size_t>(it - mid_t.begin());
        const double w = (s - mid_t[k - 1]) / (mid_t[k] - mid_t[k - 1]);
        out.push_back((1.0 - w) * v[k - 1] + w * v[k]);
      }
    }
    return out;
  }
};

raven::PerArm<TipPath> tipPaths(const fs::path& rs_file) {
  const recording::RsRecording rs = recording::readRs(rs_file);
  const auto profile = raven::builtinProfile("physical");
  raven::PerArm<TipPath> paths;
  for (raven::Arm arm : raven::kArms) {
    const auto kinematics = raven::ArmKinematics::of(profile, arm);
    TipPath& path = paths[raven::slot(arm)];
    for (std::size_t row = 0; row < rs.rows.size(); ++row) {
      path.t.push_back(rs.time(row));
      path.p.push_back(kinematics.toolPose(rs.joints(row, arm)).translation());
    }
  }
  return paths;
}

double idleTime(const raven::PerArm<TipPath>& paths) {
  double idle = 0.0;
  const TipPath& l = paths[0];
  for (std::size_t i = 1; i < l.t.size(); ++i) {
    const double dt = l.t[i] - l.t[i - 1];
    if (dt <= 0.0) continue;
    bool still = true;
    for (const TipPath& path : paths) {
      still = still && (path.p[i] - path.p[i - 1]).norm() / dt < kIdleSpeed;
    }
    if (still) idle += dt;
  }
  return idle;
}

/// Mean SPARC over the movements: per arm, each target from shown to reached (or to the end),
/// or the whole trial for an arm without targets that moved.
double meanSparc(const raven::PerArm<TipPath>& paths, const std::vector<TrialEvent>& events,
                 double end) {
  double sum = 0.0;
  int n = 0;
  const auto add = [&](double v) {
    if (std::isfinite(v)) {
      sum += v;
      ++n;
    }
  };
  for (int arm = 0; arm < 2; ++arm) {
    const TipPath& path = paths[static_cast<std::size_t>(arm)];
    std::vector<std::pair<double, double>> segments;
    double shown = kNotMeasured;
    for (const TrialEvent& e : events) {
      if (e.arm != arm) continue;
      if (e.name == "target_shown") shown = e.time;
      if (e.name == "target_reached" && std::isfinite(shown)) {
        segments.emplace_back(shown, e.time);
        shown = kNotMeasured;
      }
    }
    if (std::isfinite(shown)) segments.emplace_back(shown, end);
    const bool targets = std::any_of(events.begin(), events.end(), [&](const TrialEvent& e) {
      return e.arm == arm && e.name == "target_shown";
    });
    if (!targets && path.length(0.0, end) > 0.001) segments.emplace_back(0.0, end);
    for (const auto& [from, to] : segments) add(sparc(path.speed(from, to), kSampleRate));
  }
  return n > 0 ? sum / n : kNotMeasured;
}

/// Peak and mean (over the rows where that grasper touches something) jaw normal force.
std::pair<double, double> graspForces(const recording::CfRecording& cf) {
  raven::PerArm<std::array<std::size_t, 3>> cols;
  for (std::size_t a = 0; a < 2; ++a) {
    const std::string arm = a == 0 ? "left_" : "right_";
    cols[a] = {cf.column(arm + "jaw1_normal"), cf.column(arm + "jaw2_normal"),
               cf.column(arm + "contacts")};
  }
  double peak = 0.0, sum = 0.0;
  int rows = 0;
  for (const std::vector<double>& v : cf.rows) {
    for (const auto& c : cols) {
      const double force = v[c[0]] + v[c[1]];
      if (!(v[c[2]] > 0.0) || !std::isfinite(force)) continue;
      peak = std::max(peak, force);
      sum += force;
      ++rows;
    }
  }
  if (rows == 0) return {kNotMeasured, kNotMeasured};
  return {peak, sum / rows};
}

}  // namespace

namespace {

/// Every metric: its name, what it means, and which way is better (-1 lower, +1 higher, 0 none).
struct MetricInfo {
  const char* name;
  const char* meaning;
  int sense;
};
constexpr std::array<MetricInfo, 27> kMetrics{{
    {"completion_time_s", "s to finish (the time limit when not finished or e-stopped)", -1},
    {"completed", "1 when the task was finished within its time limit", +1},
    {"targets_reached", "targets held for the dwell time", +1},
    {"overshoots", "times a tip left its target before holding it", -1},
    {"rings_placed", "rings resting on their target posts at the end", +1},
    {"rings_dropped", "rings that fell back to the board off their target post", -1},
    {"path_length_m", "both tool tips' path (economy of motion), m", -1},
    {"path_length_left_m", "the left tool tip's path, m", -1},
    {"path_length_right_m", "the right tool tip's path, m", -1},
    {"idle_time_s", "s with both tips slower than 1 mm/s", -1},
    {"sparc", "spectral arc length per movement; closer to 0 is smoother", +1},
    {"joint_limit_hits", "iterations a target was clamped at a joint limit", -1},
    {"velocity_cap_hits", "iterations the velocity cap stretched", -1},
    {"e_stops", "times the robot e-stopped (FAULT: an amplifier overdriven, a guard)", -1},
    {"peak_grasp_force_n", "largest jaw normal force, N (material forces)", 0},
    {"mean_grasp_force_n", "mean jaw normal force while grasping, N", 0},
    {"instrument_collisions", "contact episodes of a tool with the other or the board", -1},
    {"tool_collisions", "contact episodes of the two arms with each other", -1},
    {"board_collisions", "contact episodes of a tool with the board's surface", -1},
    {"post_collisions", "contact episodes of a tool with a post", -1},
    {"excessive_force_time_s", "s a jaw pressed on anything above the task's threshold", -1},
    {"excessive_force_peak_n", "largest jaw force above the threshold, N (0: none)", -1},
    {"out_of_view_time_s", "s a tool's jaws were outside the task camera's picture, summed", -1},
    {"tip_range_left_m", "radius of the left tool tip's workspace, m", -1},
    {"tip_range_right_m", "radius of the right tool tip's workspace, m", -1},
    {"stick_range_left", "radius of the left stick's deflections (full tilt 1)", -1},
    {"stick_range_right", "radius of the right stick's deflections (full tilt 1)", -1},
}};

const MetricInfo* infoOf(const std::string& name) {
  for (const MetricInfo& m : kMetrics) {
    if (name == m.name) return &m;
  }
  return nullptr;
}

}  // namespace

const std::vector<std::string>& metricNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out;
    for (const MetricInfo& m : kMetrics) out.emplace_back(m.name);
    return out;
  }();
  return names;
}

std::string metricMeaning(const std::string& name) {
  const MetricInfo* m = infoOf(name);
  return m ? m->meaning : "";
}

int metricSense(const std::string& name) {
  const MetricInfo* m = infoOf(name);
  return m ? m->sense : 0;
}

double sparc(const std::vector<double>& speed, double rate) {
  if (speed.size() < 2) return kNotMeasured;
  const double peak = *std::max_element(speed.begin(), speed.end());
  if (!(peak > 1e-9)) return kNotMeasured;
  const auto padded = static_cast<std::size_t>(
      std::pow(2.0, std::ceil(std::log2(static_cast<double>(speed.size()))) + 4.0));
  std::vector<double> signal(speed);
  signal.resize(padded, 0.0);
  Eigen::FFT<double> fft;
  std::vector<std::complex<double>> spectrum;
  fft.fwd(spectrum, signal);
  const double df = rate / static_cast<double>(padded);
  constexpr double kCutoff = 10.0, kThreshold = 0.05;
  std::vector<double> magnitude;
  for (std::size_t k = 0; k * df <= kCutoff && k < spectrum.size(); ++k) {
    magnitude.push_back(std::abs(spectrum[k]));
  }
  const double top = *std::max_element(magnitude.begin(), magnitude.end());
  for (double& m : magnitude) m /= top;
  // The band from the first to the last frequency above the threshold.
  std::size_t first = magnitude.size(), last = 0;
  for (std::size_t k = 0; k < magnitude.size(); ++k) {
    if (magnitude[k] < kThreshold) continue;
    first = std::min(first, k);
    last = k;
  }
  if (first >= last) return 0.0;
  const double band = static_cast<double>(last - first) * df;
  double length = 0.0;
  for (std::size_t k = first + 1; k <= last; ++k) {
    length += std::hypot(df / band, magnitude[k] - magnitude[k - 1]);
  }
  return -length;
}

TrialMetrics measureTrial(const fs::path& dir) {
  const std::vector<TrialEvent> events = readEvents(dir / "events.csv");
  const auto count = [&](const char* name) {
    return static_cast<double>(std::count_if(events.begin(), events.end(),
                                             [&](const TrialEvent& e) { return e.name == name; }));
  };
  const auto end = std::find_if(events.begin(), events.end(),
                                [](const TrialEvent& e) { return e.name == "trial_end"; });
  if (end == events.end()) {
    throw recording::RecordingError((dir / "events.csv").string() +
                                    ": no trial_end event (the trial did not finish)");
  }
  const auto paths = tipPaths(fileEnding(dir, "_rs.csv"));
  const bool rings = count("rings") > 0;
  const bool targets = count("target_shown") > 0;
  // A trial not finished (out of time, or ended by an e-stop) counts at the task's time limit,
  // as the FLS scores one that was cut off (the trial_start event's value; 0 in older trials).
  const auto start = std::find_if(events.begin(), events.end(),
                                  [](const TrialEvent& e) { return e.name == "trial_start"; });
  const double limit = start != events.end() ? start->value : 0.0;
  TrialMetrics m;
  m["completion_time_s"] = end->value > 0.0 ? end->time : std::max(end->time, limit);
  m["completed"] = end->value;
  m["targets_reached"] = targets ? count("target_reached") : kNotMeasured;
  m["overshoots"] = targets ? count("target_left") : kNotMeasured;
  m["rings_placed"] = rings ? count("ring_placed") - count("ring_unplaced") : kNotMeasured;
  m["rings_dropped"] = rings ? count("ring_dropped") : kNotMeasured;
  m["path_length_left_m"] = paths[0].length(0.0, end->time);
  m["path_length_right_m"] = paths[1].length(0.0, end->time);
  m["path_length_m"] = m["path_length_left_m"] + m["path_length_right_m"];
  m["idle_time_s"] = idleTime(paths);
  m["sparc"] = meanSparc(paths, events, end->time);
  m["joint_limit_hits"] = count("joint_limit");
  m["velocity_cap_hits"] = count("velocity_cap");
  m["e_stops"] = count("robot_fault");
  const recording::CfRecording cf = recording::readCf(fileEnding(dir, "_cf.csv"));
  const auto [peak, mean] = graspForces(cf);
  m["peak_grasp_force_n"] = peak;
  m["mean_grasp_force_n"] = mean;
  measureInstruments(m, events, {paths[0].p, paths[1].p}, cf,
                     recording::readCi(fileEnding(dir, "_ci.csv")), end->time);
  return m;
}

}  // namespace study
