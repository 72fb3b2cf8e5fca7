#include "study/trial_task.hpp"

#include <fmt/format.h>

#include <cmath>
#include <random>

#include "study/peg_transfer_task.hpp"
#include "study/view_watch.hpp"

namespace study {

namespace {

/// Per arm, a sequence of points to bring the tool tip onto and hold for the dwell time.
class TargetsTask final : public TrialTask {
 public:
  TargetsTask(const TaskSpec& spec, std::uint64_t seed, raven::PerArm<bool> arms)
      : spec_(spec), offsets_(targetOffsets(spec, seed)) {
    for (std::size_t a = 0; a < 2; ++a) {
      if (!arms[a]) offsets_[a].clear();
    }
  }

  std::filesystem::path launchFile() const override { return {}; }

  void begin(const TaskView& view, EventLog& events) override {
    for (int a = 0; a < 2; ++a) {
      Arm& arm = arms_[static_cast<std::size_t>(a)];
      for (const Eigen::Vector3d& offset : offsets_[static_cast<std::size_t>(a)]) {
        arm.targets.push_back(view.tips[static_cast<std::size_t>(a)] + offset);
      }
      if (!arm.targets.empty()) events.add(view.time, "target_shown", a, 0);
    }
  }

  void observe(const TaskView& view, EventLog& events) override {
    for (int a = 0; a < 2; ++a) {
      Arm& arm = arms_[static_cast<std::size_t>(a)];
      if (arm.next >= arm.targets.size()) continue;
      const double k = static_cast<double>(arm.next);
      const bool inside = (view.tips[static_cast<std::size_t>(a)] - arm.targets[arm.next]).norm() <=
                          spec_.tolerance;
      if (inside && !arm.inside) {
        events.add(view.time, "target_entered", a, k);
        arm.entered_at = view.time;
      } else if (!inside && arm.inside) {
        events.add(view.time, "target_left", a, k);
      }
      arm.inside = inside;
      if (inside && view.time - arm.entered_at >= spec_.dwell) {
        events.add(view.time, "target_reached", a, k);
        arm.inside = false;
        if (++arm.next < arm.targets.size()) {
          events.add(view.time, "target_shown", a, static_cast<double>(arm.next));
        }
      }
    }
  }

  bool done() const override {
    return arms_[0].next >= arms_[0].targets.size() && arms_[1].next >= arms_[1].targets.size();
  }

  raven::PerArm<ArmGoal> goals() const override {
    raven::PerArm<ArmGoal> out;
    for (std::size_t a = 0; a < 2; ++a) {
      if (arms_[a].next < arms_[a].targets.size()) {
        out[a] = {true, arms_[a].targets[arms_[a].next], spec_.tolerance};
      }
    }
    return out;
  }

  std::string status(const TaskView& view) const override {
    std::string line;
    for (std::size_t a = 0; a < 2; ++a) {
      const Arm& arm = arms_[a];
      if (arm.targets.empty()) continue;
      line += a == 0 ? "left " : "   right ";
      if (arm.next >= arm.targets.size()) {
        line += "done";
        continue;
      }
      const Eigen::Vector3d d = (arm.targets[arm.next] - view.tips[a]) * 1000.0;
      line +=
          fmt::format("{}/{} {:5.1f} mm (x {:+5.1f} y {:+5.1f} z {:+5.1f}){}", arm.next + 1,
                      arm.targets.size(), d.norm(), d.x(), d.y(), d.z(), arm.inside ? " hold" : "");
    }
    return line;
  }

  /// Framed on a ball around both start points that holds every target (each is an offset from
  /// its arm's start point, so this holds in any frame), half as large again for the way there.
  viewer::View camera(const TaskView& start) const override {
    double reach = spec_.tolerance;
    for (const auto& offsets : offsets_) {
      for (const Eigen::Vector3d& offset : offsets) reach = std::max(reach, offset.norm());
    }
    const Eigen::Vector3d centre = (start.jaws[0] + start.jaws[1]) / 2.0;
    const double radius = 1.5 * ((start.jaws[0] - centre).norm() + reach + spec_.tolerance);
    return {"task", cameraHolding(centre, radius), std::nullopt};
  }

  std::optional<scenario::BoardGeometry> board() const override { return std::nullopt; }

  std::optional<raven::PerArm<Eigen::Isometry3d>> startTools() const override {
    return std::nullopt;  // where homing left them
  }

 private:
  struct Arm {
    std::vector<Eigen::Vector3d> targets;
    std::size_t next = 0;
    bool inside = false;
    double entered_at = 0.0;
  };
  TaskSpec spec_;
  raven::PerArm<std::vector<Eigen::Vector3d>> offsets_;
  raven::PerArm<Arm> arms_;
};

}  // namespace

raven::PerArm<std::vector<Eigen::Vector3d>> targetOffsets(const TaskSpec& spec,
                                                          std::uint64_t seed) {
  if (spec.pattern == "list") return {spec.left, spec.right};
  if (spec.pattern == "rectangle") {  // D_II: +x, +y, -x, -y, both arms alike
    const std::vector<Eigen::Vector3d> corners{{spec.width, 0.0, 0.0},
                                               {spec.width, spec.depth, 0.0},
                                               {0.0, spec.depth, 0.0},
                                               {0.0, 0.0, 0.0}};
    return {corners, corners};
  }
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> turn(0.0, 2.0 * M_PI), up(-spec.height, spec.height);
  raven::PerArm<std::vector<Eigen::Vector3d>> out;
  for (auto& arm : out) {
    for (int k = 0; k < spec.count; ++k) {
      const double angle = turn(rng);
      arm.emplace_back(spec.distance * std::cos(angle), spec.distance * std::sin(angle), up(rng));
    }
  }
  return out;
}

std::unique_ptr<TrialTask> makeTask(const TaskSpec& spec, std::uint64_t seed,
                                    raven::PerArm<bool> arms) {
  if (spec.kind == TaskKind::PegTransfer) return makePegTransferTask(arms);
  return std::make_unique<TargetsTask>(spec, seed, arms);
}

}  // namespace study
