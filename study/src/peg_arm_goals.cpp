#include "study/peg_arm_goals.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "raven/design/arm_design.hpp"
#include "scenario/arm_routine.hpp"
#include "scenario/grip_geometry.hpp"

namespace study {

namespace {

// The jaw axis above the ring's top at the grasp: high enough that the closed jaws make a narrow
// wedge friction holds (the scripted operator's reasoning, scenario/src/arm_routine.cpp).
constexpr double kAboveTop = 0.005;
constexpr double kLetGo = 1.0;            ///< the trigger let go (rad, jaw 1 + jaw 2)
constexpr double kApproach = 0.025;       ///< over the grasp before going down (m)
constexpr double kLift = 0.030;           ///< the ring's bottom then clears the 22 mm post
constexpr double kRise = 0.025;           ///< up after letting go
constexpr double kReleaseHeight = 0.003;  ///< the ring's bottom over the board when let go
constexpr double kSqueezeWait = 1.0;      ///< s from asking for the squeeze to lifting
constexpr double kReleaseWait = 0.8;      ///< s from letting go to rising
constexpr double kStepLimit = 15.0;       ///< s a step may take before the person moves on
// While the arm moves the motors let the jaws lean further than at rest (the wrist lags its
// command): up to 0.13 rad seen going down onto a ring. The inner jaw is kept clear of the post
// by that much more.
constexpr double kLeanSlack = 0.15;
constexpr int kAttempts = 3;  ///< grasps of one ring before it is left
/// s without getting lower on the way down, pushing, before a person sees the jaws are held up.
constexpr double kBlocked = 1.0;
// A ring held by its wall swings on the grip by a few millimetres as it is carried; one whose
// centre strays further from the jaws than this is held by something else (its post, the board).
constexpr double kStray = 0.005;
// How near the tip must be: within a ring's clearance for the grasp, looser where the move only
// has to clear something.
constexpr double kExact = 0.0006, kFine = 0.001, kCoarse = 0.0015, kLoose = 0.003;

/// How far the back of a jaw turned `angle` from the vertical reaches sideways from the jaw axis
/// at its tip: the face at the jaw's length, and the body beyond it, tapered to 60 % of its width
/// there (raven_description's jaw hull).
double jawBackAtTip(double angle) {
  const raven::design::ArmDesign jaw;
  return jaw.jaw_length * std::sin(angle) + 0.6 * jaw.jaw_width * std::cos(angle);
}

}  // namespace

PegArmGoals::PegArmGoals(const scenario::PegLayout& layout, std::vector<std::size_t> rings)
    : layout_(layout),
      rings_(std::move(rings)),
      open_(openingGrasp(layout.ring, layout.geometry.post_radius)),
      squeeze_(squeezingGrasp(layout.ring)) {
  if (rings_.empty()) step_ = Step::Done;
}

double PegArmGoals::squeezingGrasp(const scenario::RingDimensions& ring) {
  // By symmetry each jaw takes half the squeeze against the centre line: the wall seen from one
  // jaw is the whole tube with the other jaw's face replaced by the centre line (gap -w).
  const scenario::PinchedWall half{.half_width = ring.tube_half_width,
                                   .half_height = ring.half_height,
                                   .pivot_above = kAboveTop,
                                   .gap = -ring.tube_half_width,
                                   .jaw_length = raven::design::ArmDesign{}.jaw_length};
  return 2.0 * scenario::squeezingAngle(half, scenario::ArmRoutine::kDefaultSqueeze / 2.0);
}

double PegArmGoals::openingGrasp(const scenario::RingDimensions& ring, double post_radius) {
  // Each jaw's face runs from the axis to the tip on its side of the centre line. Wide enough
  // that the faces clear the tube where it is widest, a half-height under the ring's top; narrow
  // enough that the inner jaw's back clears the post the ring is on (jawBackAtTip, a sine of
  // the angle plus its phase, solved exactly). Half way between the two, each side has the same
  // angle to spare.
  const raven::design::ArmDesign jaw;
  const double widest = kAboveTop + ring.half_height;
  const double least = std::atan(ring.tube_half_width / widest);
  const double taper = 0.6 * jaw.jaw_width, reach = std::hypot(jaw.jaw_length, taper);
  const double room = ring.major_radius - post_radius;
  const double most =
      std::asin(std::clamp(room / reach, -1.0, 1.0)) - std::atan2(taper, jaw.jaw_length);
  return least + most;
}

void PegArmGoals::enter(Step step, double time) {
  step_ = step;
  since_ = time;
  lowest_ = lowered_to_ = std::numeric_limits<double>::infinity();
  lower_at_ = time;
}

void PegArmGoals::planGrasp(const scenario::RingView& ring, const Eigen::Vector3d& tip,
                            const Eigen::Matrix3d& axes) {
  const Eigen::Vector2d along = axes.col(1).head<2>().normalized();
  const Eigen::Vector3d a = ring.stationToward(along), b = ring.stationToward(-along);
  const Eigen::Vector3d station = (a - tip).head<2>().norm() <= (b - tip).head<2>().norm() ? a : b;
  centre_ = ring.centre().head<2>();
  outward_ = (station.head<2>() - centre_).normalized();
  radius_ = (station.head<2>() - centre_).norm();
  top_ = ring.top();
  // The post inside the ring, if it is on one: the inner jaw goes down beside it.
  const auto& job = layout_.jobs[rings_[next_]];
  post_ = std::nullopt;
  for (const Eigen::Vector2d& p : {job.from, job.to}) {
    if (ring.threadedOn(p)) post_ = p;
  }
  planned_ = true;
}

Eigen::Vector3d PegArmGoals::graspFor(const Eigen::Matrix3d& axes, double opening) const {
  // In the plane of the jaws (outward from the ring's centre, and up), the jaws lean by `lean`
  // outward (the motors hold the wrist only so well). The jaw axis goes where each jaw clears
  // what it must: the faces the tube where it is widest (a half-height under its top), the
  // inner jaw's back (tapered to 60 % at its tip) the post, leaning kLeanSlack more; half way
  // between the nearest and the farthest place that does, or clear of the post if none does.
  const Eigen::Vector3d x = axes.col(0);
  const Eigen::Vector2d tangent(-outward_.y(), outward_.x());
  const double down = std::max(-x.z(), 0.5);
  const double lean = std::atan2(x.head<2>().dot(outward_), down);
  const double inner = opening / 2.0 - lean, outer = opening / 2.0 + lean;
  const double widest = kAboveTop + layout_.ring.half_height;
  const double w = layout_.ring.tube_half_width;
  double nearest = radius_ + w - widest * std::tan(outer);
  if (post_) {
    nearest = std::max(nearest, (*post_ - centre_).dot(outward_) + layout_.geometry.post_radius +
                                    post_clearance_ + jawBackAtTip(inner + kLeanSlack));
  }
  const double farthest = radius_ - w + widest * std::tan(inner);
  const double across = farthest >= nearest ? 0.5 * (nearest + farthest) : nearest;
  // Along the tube, the jaws' lean that way is made up so that they cross it at the station.
  const double sideways = -widest * x.head<2>().dot(tangent) / down;
  const Eigen::Vector2d at = centre_ + across * outward_ + sideways * tangent;
  return Eigen::Vector3d(at.x(), at.y(), top_ + kAboveTop);
}

void PegArmGoals::retry(const scenario::RingView& ring, double time) {
  const auto& job = layout_.jobs[rings_[next_]];
  planned_ = false;
  if (!scenario::restsOn(ring, job.to, layout_.geometry) && ++attempts_ < kAttempts) {
    enter(Step::Over, time);
    return;
  }
  attempts_ = 0;
  post_clearance_ = 0.0;
  enter(++next_ < rings_.size() ? Step::Over : Step::Done, time);
}

void PegArmGoals::observe(double time, const Eigen::Vector3d& tip, const Eigen::Matrix3d& axes,
                          const std::vector<scenario::RingView>& seen) {
  if (step_ == Step::Done) {
    goal_ = {};
    return;
  }
  const scenario::RingView& ring = seen[rings_[next_]];
  const auto& job = layout_.jobs[rings_[next_]];
  const bool stuck = time - since_ > kStepLimit;
  const Eigen::Vector2d held_at = (tip - ring.centre()).head<2>();  // the tip from the ring
  // The ring's hole around a post: the tool goes where that puts the ring.
  const auto around = [&](const Eigen::Vector2d& post, double z) {
    return Eigen::Vector3d(post.x() + held_at.x(), post.y() + held_at.y(), z);
  };
  // Carried, the ring stays where it was in the jaws; one that strays is not coming along.
  const bool held = (held_at - carried_).norm() <= kStray;
  // Going down, the tool is held up when it is shoved back up, or has not got lower for a while
  // of pushing.
  lowest_ = std::min(lowest_, tip.z());
  if (tip.z() < lowered_to_ - kFine) lowered_to_ = tip.z(), lower_at_ = time;
  const bool held_up = tip.z() > lowest_ + kFine || time - lower_at_ > kBlocked;
  switch (step_) {
    case Step::Over:
      if (!planned_) planGrasp(ring, tip, axes);
      grasp_ = graspFor(axes, open_);
      goal_ = {true, grasp_ + Eigen::Vector3d(0, 0, kApproach), kExact, open_};
      if (reached(tip) || stuck) enter(Step::Down, time);
      break;
    case Step::Down:  // beside the post: aligned again before going lower whenever it drifts
      grasp_ = graspFor(axes, open_);
      // Held up on the way down (a jaw on the post's top or the ring's): up again, and down
      // keeping more room from the post. It counts as a try of this ring.
      if (held_up && tip.z() > grasp_.z() + kCoarse) {
        post_clearance_ += kFine;
        retry(ring, time);
      } else if ((grasp_ - tip).head<2>().norm() > kFine) {
        goal_ = {true, Eigen::Vector3d(grasp_.x(), grasp_.y(), tip.z()), kExact, open_};
        lower_at_ = time;
      } else {
        goal_ = {true, grasp_, kFine, open_};
        if (reached(tip) || stuck) enter(Step::Squeeze, time);
      }
      break;
    case Step::Squeeze:
      goal_ = {true, grasp_, kLoose, squeeze_};
      carried_ = held_at;
      if (time - since_ >= kSqueezeWait) enter(Step::Lift, time);
      break;
    case Step::Lift:  // the ring straight up its post (the tool straight up if it slipped out)
      goal_ = {true,
               held ? around(post_.value_or(centre_), grasp_.z() + kLift)
                    : Eigen::Vector3d(tip.x(), tip.y(), grasp_.z() + kLift),
               kCoarse, squeeze_};
      if (held) carried_ = held_at;
      if (reached(tip) || stuck) {
        enter(layout_.geometry.offTheBoard(ring.bottom()) ? Step::Carry : Step::Release, time);
      }
      break;
    case Step::Carry:
      goal_ = {true, around(job.to, grasp_.z() + kLift), kCoarse, squeeze_};
      if (!held) {
        enter(Step::Release, time);
      } else if (reached(tip) || stuck) {
        enter(Step::Lower, time);
      }
      break;
    case Step::Lower: {  // until the ring's bottom is just over the board
      const double drop = ring.bottom() - layout_.geometry.board_top - kReleaseHeight;
      goal_ = {true, around(job.to, tip.z() - drop), kFine, squeeze_};
      if (!held || drop <= kFine || held_up || stuck) enter(Step::Release, time);
      break;
    }
    case Step::Release:
      goal_ = {true, tip, kLoose, kLetGo};
      if (time - since_ >= kReleaseWait) {
        goal_.point = tip + Eigen::Vector3d(0, 0, kRise);
        enter(Step::Rise, time);
      }
      break;
    case Step::Rise:
      if (reached(tip) || stuck) retry(ring, time);
      break;
    case Step::Done:
      break;
  }
}

}  // namespace study
