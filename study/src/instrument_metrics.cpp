#include "study/instrument_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "not_measured.hpp"
#include "study/collision_watch.hpp"
#include "study/protocol.hpp"

namespace study {

ExcessiveForce excessiveForce(const recording::CfRecording& cf, double threshold) {
  const std::size_t time = cf.column("time");
  std::vector<std::size_t> jaws;
  for (const char* arm : {"left_", "right_"}) {
    for (const char* jaw : {"jaw1_normal", "jaw2_normal"}) {
      jaws.push_back(cf.column(std::string(arm) + jaw));
    }
  }
  ExcessiveForce out;
  for (std::size_t r = 0; r < cf.rows.size(); ++r) {
    double hardest = 0.0;
    for (std::size_t column : jaws) {
      const double f = cf.rows[r][column];
      if (std::isfinite(f)) hardest = std::max(hardest, f);
    }
    if (hardest <= threshold) continue;
    out.peak = std::max(out.peak, hardest);
    if (r > 0) out.time += cf.rows[r][time] - cf.rows[r - 1][time];
  }
  return out;
}

double timeBetween(const std::vector<TrialEvent>& events, const std::string& begin,
                   const std::string& end, double trial_end) {
  std::map<int, double> since;  // arm -> when its open interval began
  double total = 0.0;
  for (const TrialEvent& e : events) {
    if (e.name == begin && !since.contains(e.arm)) since[e.arm] = e.time;
    if (e.name == end && since.contains(e.arm)) {
      total += e.time - since[e.arm];
      since.erase(e.arm);
    }
  }
  for (const auto& [arm, from] : since) total += trial_end - from;
  return total;
}

void measureInstruments(TrialMetrics& m, const std::vector<TrialEvent>& events,
                        const raven::PerArm<std::vector<Eigen::Vector3d>>& tips,
                        const recording::CfRecording& cf,
                        const std::vector<recording::GamepadState>& sticks, double end) {
  const auto episodes = [&](CollisionKind kind) {
    return static_cast<double>(std::count_if(events.begin(), events.end(), [&](const auto& e) {
      return e.name == collisionEvent(kind);
    }));
  };
  const bool board = std::any_of(events.begin(), events.end(),
                                 [](const TrialEvent& e) { return e.name == "rings"; });
  m["tool_collisions"] = episodes(CollisionKind::Tool);
  m["board_collisions"] = board ? episodes(CollisionKind::Board) : kNotMeasured;
  m["post_collisions"] = board ? episodes(CollisionKind::Post) : kNotMeasured;
  m["instrument_collisions"] =
      m["tool_collisions"] + (board ? m["board_collisions"] + m["post_collisions"] : 0.0);
  const auto threshold = std::find_if(events.begin(), events.end(), [](const TrialEvent& e) {
    return e.name == "force_threshold";
  });
  const ExcessiveForce force =
      excessiveForce(cf, threshold == events.end() ? TaskSpec{}.excessive_force : threshold->value);
  m["excessive_force_time_s"] = force.time;
  m["excessive_force_peak_n"] = force.peak;
  m["out_of_view_time_s"] = timeBetween(events, "out_of_view", "in_view", end);
  m["tip_range_left_m"] = workspaceRange(tips[0]);
  m["tip_range_right_m"] = workspaceRange(tips[1]);
  std::vector<Eigen::Vector3d> left, right;
  for (const recording::GamepadState& pad : sticks) {
    left.emplace_back(pad.left_x, pad.left_y, 0.0);
    right.emplace_back(pad.right_x, pad.right_y, 0.0);
  }
  m["stick_range_left"] = workspaceRange(left);
  m["stick_range_right"] = workspaceRange(right);
}

double workspaceRange(const std::vector<Eigen::Vector3d>& points) {
  double widest = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    for (std::size_t j = i + 1; j < points.size(); ++j) {
      widest = std::max(widest, (points[i] - points[j]).squaredNorm());
    }
  }
  return std::sqrt(widest) / 2.0;
}

}  // namespace study
