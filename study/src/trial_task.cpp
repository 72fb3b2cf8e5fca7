#include "study/trial_task.hpp"

#include <fmt/format.h>

#include <cmath>
#include <random>

#include "raven/platform_profile.hpp"
#include "scenario/peg_layout.hpp"
#include "scenario/ring_nodes.hpp"
#include "scenario/task_views.hpp"
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

  bool virtualParticipantsCan() const override { return true; }

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

/// The six rings of the peg-transfer scene, each from its start post to the post behind it.
class PegTransferTask final : public TrialTask {
 public:
  std::filesystem::path launchFile() const override {
    return raven::modelDirectory() / "peg_transfer" / "launch.yaml";
  }

  void begin(const TaskView& view, EventLog& events) override {
    for (std::size_t i = 0; i < 6; ++i) {
      rings_[i] = &view.world->softBody(layout_.jobs[i].ring);
    }
    events.add(view.time, "rings", -1, 6);
    observe(view, events);
  }

  void observe(const TaskView& view, EventLog& events) override {
    const scenario::BoardGeometry& g = layout_.geometry;
    for (std::size_t i = 0; i < 6; ++i) {
      const scenario::RingJob& job = layout_.jobs[i];
      const int arm = raven::index(job.arm);
      const double ring = static_cast<double>(i + 1);
      const scenario::RingNodes s = scenario::inspect(*rings_[i]);
      const scenario::RingView seen({view.time, rings_[i]->pose(), std::nullopt}, layout_.ring);
      const bool placed = scenario::restsOn(seen, job.to, g);
      const bool off = g.offTheBoard(seen.bottom());
      Ring& r = state_[i];
      if (off && !r.lifted) events.add(view.time, "ring_lifted", arm, ring);
      if (placed && !r.placed) events.add(view.time, "ring_placed", arm, ring);
      if (!placed && r.placed) events.add(view.time, "ring_unplaced", arm, ring);
      // Down on the board again, resting, somewhere other than its target post: dropped.
      if (r.lifted && !off && !placed && s.speed < 0.01) {
        events.add(view.time, "ring_dropped", arm, ring);
        r.lifted = false;
      }
      if (off) r.lifted = true;
      if (placed) r.lifted = false;
      r.placed = placed;
    }
  }

  bool done() const override {
    for (const Ring& r : state_) {
      if (!r.placed) return false;
    }
    return true;
  }

  raven::PerArm<ArmGoal> goals() const override { return {}; }

  std::string status(const TaskView&) const override {
    int placed = 0, carried = 0;
    for (const Ring& r : state_) {
      placed += r.placed ? 1 : 0;
      carried += r.lifted ? 1 : 0;
    }
    return fmt::format("rings placed {}/6, off the board {}", placed, carried);
  }

  /// The overview: both work areas, every ring on its post can be counted.
  viewer::View camera(const TaskView& start) const override {
    return scenario::pegTransferViews(*start.world, layout_).front();
  }

  std::optional<scenario::BoardGeometry> board() const override { return layout_.geometry; }

  bool virtualParticipantsCan() const override { return false; }

 private:
  struct Ring {
    bool lifted = false;  ///< off the board since it last rested
    bool placed = false;
  };
  scenario::PegLayout layout_;
  std::array<const ambf_like::SoftBody*, 6> rings_{};
  std::array<Ring, 6> state_;
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
  if (spec.kind == TaskKind::PegTransfer) return std::make_unique<PegTransferTask>();
  return std::make_unique<TargetsTask>(spec, seed, arms);
}

}  // namespace study
