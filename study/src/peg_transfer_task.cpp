#include "study/peg_transfer_task.hpp"

#include <fmt/format.h>

#include "raven/platform_profile.hpp"
#include "scenario/peg_layout.hpp"
#include "scenario/ring_nodes.hpp"
#include "scenario/task_views.hpp"
#include "study/peg_arm_goals.hpp"

namespace study {

namespace {

/// The trial's start: the jaw axis this high over the board (m), above the 22 mm posts.
constexpr double kStartHeight = 0.045;

/// The six rings of the peg-transfer scene, each from its start post to the post behind it.
class PegTransferTask final : public TrialTask {
 public:
  explicit PegTransferTask(raven::PerArm<bool> arms)
      : plans_{PegArmGoals(layout_, ringsOf(raven::Arm::Left, arms[0])),
               PegArmGoals(layout_, ringsOf(raven::Arm::Right, arms[1]))} {
    for (std::size_t i = 0; i < 6; ++i) state_[i].moved = arms[raven::slot(layout_.jobs[i].arm)];
  }

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
    std::vector<scenario::RingView> seen;
    for (std::size_t i = 0; i < 6; ++i) {
      const scenario::RingJob& job = layout_.jobs[i];
      const int arm = raven::index(job.arm);
      const double ring = static_cast<double>(i + 1);
      const scenario::RingNodes s = scenario::inspect(*rings_[i]);
      seen.emplace_back(bridge::Sighting{view.time, rings_[i]->pose(), std::nullopt}, layout_.ring);
      const bool placed = scenario::restsOn(seen.back(), job.to, g);
      const bool off = g.offTheBoard(seen.back().bottom());
      Ring& r = state_[i];
      if (off && !r.lifted) events.add(view.time, "ring_lifted", arm, ring);
      if (placed && !r.placed) events.add(view.time, "ring_placed", arm, ring);
      if (!placed && r.placed) events.add(view.time, "ring_unplaced", arm, ring);
      // Down on the board again, resting, somewhere other than around its target post: dropped
      // (one let go over its post may rest a moment before it settles there).
      if (r.lifted && !off && !seen.back().threadedOn(job.to) && s.speed < 0.01) {
        events.add(view.time, "ring_dropped", arm, ring);
        r.lifted = false;
      }
      if (off) r.lifted = true;
      if (placed) r.lifted = false;
      r.placed = placed;
    }
    for (std::size_t a = 0; a < 2; ++a) {
      plans_[a].observe(view.time, view.tips[a], view.tool_axes[a], seen);
    }
  }

  bool done() const override {
    for (const Ring& r : state_) {
      if (r.moved && !r.placed) return false;
    }
    return true;
  }

  raven::PerArm<ArmGoal> goals() const override { return {plans_[0].goal(), plans_[1].goal()}; }

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

  /// Over the middle of each arm's six posts, jaws down, opening across the rows (x), so they
  /// close across a ring's wall at its sides.
  std::optional<raven::PerArm<Eigen::Isometry3d>> startTools() const override {
    raven::PerArm<Eigen::Isometry3d> out;
    for (raven::Arm arm : raven::kArms) {
      Eigen::Vector2d middle = Eigen::Vector2d::Zero();
      int posts = 0;
      for (const scenario::RingJob& job : layout_.jobs) {
        if (job.arm != arm) continue;
        middle += job.from + job.to;
        posts += 2;
      }
      Eigen::Isometry3d& tool = out[raven::slot(arm)];
      tool.setIdentity();
      tool.linear().col(0) = Eigen::Vector3d(0, 0, -1);  // the jaws point down
      tool.linear().col(1) = Eigen::Vector3d(1, 0, 0);   // jaw 1 opens along x
      tool.linear().col(2) = Eigen::Vector3d(0, -1, 0);
      tool.translation() << middle / posts, layout_.geometry.board_top + kStartHeight;
    }
    return out;
  }

 private:
  struct Ring {
    bool lifted = false;  ///< off the board since it last rested
    bool placed = false;
    bool moved = true;  ///< its arm is driven in this trial
  };
  /// The jobs (indices) of `arm`, none when it does not move.
  std::vector<std::size_t> ringsOf(raven::Arm arm, bool moves) const {
    std::vector<std::size_t> out;
    for (std::size_t i = 0; i < layout_.jobs.size(); ++i) {
      if (moves && layout_.jobs[i].arm == arm) out.push_back(i);
    }
    return out;
  }

  scenario::PegLayout layout_;
  std::array<const ambf_like::SoftBody*, 6> rings_{};
  std::array<Ring, 6> state_;
  raven::PerArm<PegArmGoals> plans_;
};

}  // namespace

std::unique_ptr<TrialTask> makePegTransferTask(raven::PerArm<bool> arms) {
  return std::make_unique<PegTransferTask>(arms);
}

}  // namespace study
