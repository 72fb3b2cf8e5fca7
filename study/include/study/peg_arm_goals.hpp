#pragma once
// What a person at the pad aims one arm at in the peg transfer, ring by ring, with the grasper
// held jaws down as the trial starts it: over the ring's wall where the jaws close across it,
// down onto it, a squeeze of the trigger, up until the ring clears its post, over the target
// post (the ring's hole, not the tool, lined up with it), down until the ring nearly touches the
// board, the trigger let go, and up again. A ring that did not come up, fell, or missed its post
// is taken again from where it lies (twice at most, then left), as a person watching it would; a
// way down held up on a post is such a try, the next with more room kept from the post.
// These are the steps a trainer would call out; the hands (VirtualParticipant) do the steering.

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "scenario/peg_layout.hpp"
#include "scenario/ring_view.hpp"
#include "study/trial_task.hpp"

namespace study {

/// One arm's goals through its rings of the peg transfer.
class PegArmGoals {
 public:
  /// `rings`: this arm's jobs (indices into `layout.jobs`), in order.
  PegArmGoals(const scenario::PegLayout& layout, std::vector<std::size_t> rings);

  /// The jaw opening (jaw 1 + jaw 2, rad) that squeezes a ring's wall by the scripted operator's
  /// squeeze (scenario::ArmRoutine::kDefaultSqueeze) between two jaws closing symmetrically on
  /// its centre line, the jaw axis kAboveTop over the ring (grip_geometry.hpp).
  static double squeezingGrasp(const scenario::RingDimensions& ring);
  /// The jaw opening with which open jaws go down on either side of a ring's wall, the ring
  /// on a post of `post_radius`: the trigger pressed a little, not let go (1 rad would put the
  /// inner jaw on the post).
  static double openingGrasp(const scenario::RingDimensions& ring, double post_radius);

  /// After an iteration at `time`: the tool tip, the tool's axes (TaskView::tool_axes), and
  /// every ring of the scene as seen (layout order).
  void observe(double time, const Eigen::Vector3d& tip, const Eigen::Matrix3d& axes,
               const std::vector<scenario::RingView>& seen);
  ArmGoal goal() const { return goal_; }
  bool done() const { return step_ == Step::Done; }

 private:
  enum class Step { Over, Down, Squeeze, Lift, Carry, Lower, Release, Rise, Done };
  void enter(Step step, double time);
  /// Plans the grasp of the current ring as it lies: the jaws straddle the point of its centre
  /// line on the side nearer the tip where they close across it.
  void planGrasp(const scenario::RingView& ring, const Eigen::Vector3d& tip,
                 const Eigen::Matrix3d& axes);
  /// Where the jaw axis goes for the planned grasp, the jaws opened by `opening` and leaning as
  /// `axes` says (the wrist-locked mapping keeps the wrist's joints, not its orientation, and
  /// the motors hold them only so well): every jaw clear of the tube and the post.
  Eigen::Vector3d graspFor(const Eigen::Matrix3d& axes, double opening) const;
  /// After the rise or a descent held up: the same ring again, the next one, or done.
  void retry(const scenario::RingView& ring, double time);
  bool reached(const Eigen::Vector3d& tip) const {
    return (tip - goal_.point).norm() <= goal_.tolerance;
  }

  scenario::PegLayout layout_;
  std::vector<std::size_t> rings_;
  std::size_t next_ = 0;  ///< index into rings_
  int attempts_ = 0;      ///< of the current ring
  Step step_ = Step::Over;
  bool planned_ = false;         ///< the current attempt's grasp is planned
  double since_ = 0.0;           ///< s: when the current step began
  double lowest_ = 0.0;          ///< the tip's lowest height in this step
  double lowered_to_ = 0.0;      ///< the height where it last got a step (kFine) lower
  double lower_at_ = 0.0;        ///< s: when it did (or was re-aligned)
  double post_clearance_ = 0.0;  ///< more room from the post after a jaw was held up on it
  double open_;                  ///< the jaw opening going down on a ring
  double squeeze_;               ///< the jaw opening of a squeeze
  // The planned grasp, horizontally: the ring's centre, the way out to the grasped side, the
  // centre line's radius there, the post it is on (none: not on a post); its top.
  Eigen::Vector2d centre_ = Eigen::Vector2d::Zero(), outward_ = Eigen::Vector2d::UnitX();
  double radius_ = 0.0, top_ = 0.0;
  std::optional<Eigen::Vector2d> post_;
  Eigen::Vector3d grasp_ = Eigen::Vector3d::Zero();    ///< the jaw axis there
  Eigen::Vector2d carried_ = Eigen::Vector2d::Zero();  ///< the tip from the ring as it came up
  ArmGoal goal_;
};

}  // namespace study
