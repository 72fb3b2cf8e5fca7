#include "scenario/arm_routine.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "raven/design/arm_design.hpp"
#include "scenario/grip_geometry.hpp"

namespace scenario {

namespace {

constexpr double kOpen = 1.3;      ///< the outer jaw's angle when open (rad): clear of the ring
constexpr double kJawStep = 0.05;  ///< jaw angle per iteration
constexpr double kStep = 0.001;    ///< tool travel per iteration (m)
// The jaw axis above the ring's top at the grasp. A jaw hinged above a tube meets it above its
// widest point, so the two faces make a wedge that pushes the tube down and out of the jaws, and
// friction holds it only while the wedge is narrow (half-angle under atan mu). The higher the
// hinge, the narrower the wedge: 5 mm up, the closed outer jaw stands 0.47 rad from the inner
// one (0.58 rad 3.5 mm up, where the ideal twin re-grasped 34 rings of 120 on seeds 1-20).
constexpr double kAboveTop = 0.005;
constexpr double kGap = 0.0002;  ///< the inner jaw's face from the wall
// The inner jaw goes down between the tube and the post, about 1 mm from each on a centred
// ring; a ring pushed off its post's axis leaves less room on one side. A re-grasp takes the
// side away from the target row unless another side of that half has this much more room.
constexpr double kRoomier = 0.0004;
const Eigen::Vector2d kAwayFromTargets(0.0, -1.0);  ///< the target row is at +y
constexpr std::array<double, 4> kOtherSides{-M_PI / 4, M_PI / 4, -M_PI / 2, M_PI / 2};
constexpr double kApproach = 0.025;  ///< the orientation move ends this far above the grasp
constexpr double kLift = 0.030;      ///< the ring's bottom clears the 22 mm post
constexpr double kRetreat = 0.025;
constexpr double kReleaseHeight = 0.0015;  ///< the ring's bottom above the board when let go
constexpr int kSettleIterations = 15;
constexpr double kAligned = 0.0001;   ///< the measured tool this near the grasp before closing (m)
constexpr int kAlignIterations = 60;  ///< ... or this many iterations of correcting
constexpr double kStill = 0.00002;    ///< the measured tool moved less in an iteration (m)
// In free space the arm's motors stop at most about 1 mm short of a command (their joints have no
// integrator: friction and the weight the firmware misjudges hold them off); a command that has
// to go further than this beyond the grasp is pressing the tool against something.
constexpr double kAlignReach = 0.002;
// The measured tool lags the command by up to 3 mm while it moves (the motors' tracking); twice
// that means something stops it, and pushing on only winds the arm's amplifiers up.
constexpr double kBlockedLag = 0.006;
constexpr double kJawReached = 0.01;  ///< a measured tool joint this near its command (rad)
constexpr int kJawIterations = 30;    ///< ... or this many iterations of waiting for them
// Lifted off the board, a gripped ring swings the tool: the board's reaction, which the tool's
// integrators wound against while the jaws closed, is gone, and they take about a second to bring
// roll, wrist and jaws back. A person waits for the ring to hang still before carrying it.
constexpr int kHangIterations = 150;  ///< ... at most this many iterations
// Holding a ring, the jaws stop anywhere within their motors' friction band around the command, a
// few mrad either way, and the squeeze follows the measured opening (about 110 N per rad on the
// nominal ring: docs/main-job.md). Watching the jaws, the operator trims the outer jaw's command
// by this share of the opening's lack each iteration (about a second to settle, slower than the
// jaw motors' own loop), at most kGripTrim from the grasp's angle.
constexpr double kGripGain = 0.1;
constexpr double kGripTrim = 0.02;   ///< rad
constexpr double kCentred = 0.0005;  ///< the ring's centre this near the post's axis (m)
// A ring held by its wall swings on the grip by a few millimetres as it is carried; one whose
// centre strays further from the jaws than this since it came up is held by something else (its
// post, the board) and is not coming along: centring by sight would chase it without end.
constexpr double kCarriedStray = 0.005;
constexpr int kCentringIterations = 40;  ///< ... or this many iterations of trying
constexpr int kMaxRegrasps = 2;          ///< per ring, as an operator would before moving on

}  // namespace

std::string_view phaseName(Phase phase) {
  static constexpr std::array<std::string_view, 11> names{"orient", "descend", "align", "close",
                                                          "lift",   "carry",   "lower", "open",
                                                          "settle", "retreat", "done"};
  return names[static_cast<std::size_t>(phase)];
}

ArmRoutine::ArmRoutine(raven::Arm arm, const raven::PlatformProfile& profile,
                       const PegLayout& layout, std::vector<RingJob> jobs, double squeeze)
    : arm_(arm),
      profile_(profile),
      kinematics_(raven::ArmKinematics::of(profile, arm)),
      layout_(layout),
      jobs_(std::move(jobs)),
      regrasps_(jobs_.size(), 0),
      closed_(jawAngleFor(squeeze)) {
  if (jobs_.empty()) phase_ = Phase::Done;
}

RingView ArmRoutine::ring(const bridge::ScenePerception& scene) const {
  return RingView(scene.sight(jobs_[job_].ring), layout_.ring);
}

ArmRoutine::Grasp ArmRoutine::graspOn(const RingView& seen, const Eigen::Vector2d& toward) const {
  const Eigen::Vector2d centre = seen.centre().head<2>();
  // The station: the tube's centre line on that side.
  const Eigen::Vector3d station = seen.stationToward(toward);
  const Eigen::Vector2d inward = (centre - station.head<2>()).normalized();
  // Jaws down; jaw 1 (the inner one) swings towards grasp_scale's side of the tool's y axis.
  const double side = profile_.arm(arm_).grasp_scale > 0 ? 1.0 : -1.0;
  const Eigen::Vector3d x(0, 0, -1), y = side * Eigen::Vector3d(inward.x(), inward.y(), 0);
  Grasp grasp;
  grasp.orientation.col(0) = x;
  grasp.orientation.col(1) = y;
  grasp.orientation.col(2) = x.cross(y);
  const Eigen::Vector2d face = station.head<2>() + inward * (layout_.ring.tube_half_width + kGap);
  grasp.pivot = Eigen::Vector3d(face.x(), face.y(), seen.top() + kAboveTop);
  grasp.offset = face - centre;
  return grasp;
}

Eigen::Vector2d ArmRoutine::graspSide(const RingView& seen) const {
  const RingJob& job = jobs_[job_];
  const Eigen::Vector2d centre = seen.centre().head<2>();
  const Eigen::Vector2d post =
      (centre - job.from).norm() <= (centre - job.to).norm() ? job.from : job.to;
  // The room between the tube and the post on side u grows by (centre - post) . u.
  const Eigen::Vector2d off = centre - post;
  const auto room = [&](const Eigen::Vector2d& side) { return off.dot(side); };
  Eigen::Vector2d roomiest = kAwayFromTargets;
  for (const double turn : kOtherSides) {
    const Eigen::Vector2d side = Eigen::Rotation2Dd(turn) * kAwayFromTargets;
    if (room(side) > room(roomiest)) roomiest = side;
  }
  return room(roomiest) > room(kAwayFromTargets) + kRoomier ? roomiest : kAwayFromTargets;
}

double ArmRoutine::jawAngleFor(double squeeze) const {
  const PinchedWall wall{.half_width = layout_.ring.tube_half_width,
                         .half_height = layout_.ring.half_height,
                         .pivot_above = kAboveTop,
                         .gap = kGap,
                         .jaw_length = raven::design::ArmDesign{}.jaw_length};
  return squeezingAngle(wall, squeeze);
}

raven::ArmJoints ArmRoutine::withJaws(raven::ArmJoints q) const {
  q(raven::kJaw1) = inner_;
  q(raven::kJaw2) = outer_;
  return q;
}

std::optional<raven::ArmJoints> ArmRoutine::overRing(const raven::ArmJoints& target) const {
  Eigen::Isometry3d above = Eigen::Isometry3d::Identity();
  above.linear() = grasp_.orientation;
  above.translation() = grasp_.pivot + Eigen::Vector3d(0, 0, kApproach);
  auto best = kinematics_.inverseWithinLimits(above, opening(), target);
  if (best) *best = withJaws(*best);
  return best;
}

raven::ArmJoints ArmRoutine::translate(const raven::ArmJoints& target, const Eigen::Vector3d& goal,
                                       double step, bool& arrived) const {
  const Eigen::Vector3d tool = kinematics_.toolPose(target).translation();
  Eigen::Vector3d delta = goal - tool;
  arrived = delta.norm() <= step;
  if (!arrived) delta *= step / delta.norm();
  // The wrist is locked: the wrist point moves as the tool point does.
  const auto solution =
      kinematics_.inverseWristLocked(kinematics_.wristPoint(target) + delta, target, profile_.home);
  if (!solution.ok || solution.clamp.any()) {  // out of reach: give the step up and carry on
    arrived = true;
    return target;
  }
  return withJaws(solution.joints);
}

void ArmRoutine::advance(Phase next) {
  phase_ = next;
  waited_ = 0;
}

bool ArmRoutine::decideToRegrasp(const char* why) {
  if (regrasps_[job_] >= kMaxRegrasps) return false;
  ++regrasps_[job_];
  retrying_ = true;
  spdlog::info("{} arm: {} {}; grasping it again ({} of {})", raven::armName(arm_),
               jobs_[job_].ring, why, regrasps_[job_], kMaxRegrasps);
  return true;
}

bool ArmRoutine::jawsOnCommand(const raven::ArmJoints& measured) const {
  return std::abs(measured(raven::kJaw1) - inner_) <= kJawReached &&
         std::abs(measured(raven::kJaw2) - outer_) <= kJawReached;
}

void ArmRoutine::keepGrip(const raven::ArmJoints& measured) {
  const double lack = inner_ + closed_ - (measured(raven::kJaw1) + measured(raven::kJaw2));
  outer_ = std::clamp(outer_ + kGripGain * lack, closed_ - kGripTrim, closed_ + kGripTrim);
}

bool ArmRoutine::toolOnCommand(const raven::ArmJoints& target,
                               const raven::ArmJoints& measured) const {
  return std::abs(measured(raven::kRoll) - target(raven::kRoll)) <= kJawReached &&
         std::abs(measured(raven::kWrist) - target(raven::kWrist)) <= kJawReached &&
         jawsOnCommand(measured);
}

bool ArmRoutine::blocked(const raven::ArmJoints& target, const raven::ArmJoints& measured) const {
  const bool moving = phase_ == Phase::Descend || phase_ == Phase::Align || phase_ == Phase::Lift ||
                      phase_ == Phase::Carry || phase_ == Phase::Lower || phase_ == Phase::Retreat;
  return moving &&
         (kinematics_.toolPose(target).translation() - kinematics_.toolPose(measured).translation())
                 .norm() > kBlockedLag;
}

raven::ArmJoints ArmRoutine::easeOff(const raven::ArmJoints& measured) {
  spdlog::debug("{} arm, {}: the tool was blocked while it {}; easing off where it is",
                raven::armName(arm_), jobs_[job_].ring, phaseName(phase_));
  if (phase_ == Phase::Descend) {  // it met the ring or its post: grasp it again from above
    if (decideToRegrasp("blocked the jaws on their way down")) {
      advance(Phase::Open);
    } else {
      retrying_ = false;
      advance(Phase::Retreat);
    }
  } else if (phase_ == Phase::Align) {  // as near the grasp as it goes: close there
    advance(Phase::Close);
  } else if (phase_ == Phase::Lower) {  // the ring is on something: let it go there
    advance(Phase::Open);
  }
  return withJaws(measured);
}

bool ArmRoutine::ringFollows(const bridge::ScenePerception& scene) const {
  return layout_.geometry.offTheBoard(ring(scene).bottom());
}

raven::ArmJoints ArmRoutine::next(const raven::ArmJoints& target, const raven::ArmJoints& measured,
                                  const bridge::ScenePerception& scene) {
  const Phase before = phase_;
  const std::size_t job = job_;
  if (blocked(target, measured)) return easeOff(measured);
  const raven::ArmJoints q = stepPhase(target, measured, scene);
  if (phase_ != before) logTransition(before, job, q, scene);
  return q;
}

raven::ArmJoints ArmRoutine::stepPhase(const raven::ArmJoints& target,
                                       const raven::ArmJoints& measured,
                                       const bridge::ScenePerception& scene) {
  bool arrived = false;
  raven::ArmJoints q = target;
  switch (phase_) {
    case Phase::Orient:
      return orient(target, scene);
    case Phase::Descend:
      q = translate(target, grasp_.pivot, kStep, arrived);
      if (arrived) advance(Phase::Align);
      return q;
    case Phase::Align:
      return align(target, measured);
    case Phase::Close: {  // the jaws to the grasp's angle, then until the measured jaws are there
      const bool commanded = outer_ <= closed_;
      outer_ = std::max(closed_, outer_ - kJawStep);
      // The jaw motors' integrators bring the jaws onto their command once the ring stops them.
      if (commanded && (jawsOnCommand(measured) || ++waited_ > kJawIterations))
        advance(Phase::Lift);
      return withJaws(target);
    }
    case Phase::Lift:
      q = translate(target, grasp_.pivot + Eigen::Vector3d(0, 0, kLift), kStep, arrived);
      if (!arrived) return q;
      keepGrip(measured);
      q = withJaws(q);
      if (!toolOnCommand(q, measured) && ++waited_ <= kHangIterations) return q;
      if (!ringFollows(scene) && decideToRegrasp("did not come up with the jaws")) {
        advance(Phase::Open);
      } else {
        grasp_.lifted_offset =
            kinematics_.toolPose(q).translation().head<2>() - ring(scene).centre().head<2>();
        advance(Phase::Carry);
      }
      return q;
    case Phase::Carry:
      keepGrip(measured);
      return withJaws(carry(target, scene));
    case Phase::Lower:
      keepGrip(measured);
      return withJaws(lower(target, scene));
    case Phase::Open:
      outer_ = std::min(kOpen, outer_ + kJawStep);
      if (outer_ >= kOpen) advance(Phase::Settle);
      return withJaws(target);
    case Phase::Settle:
      if (++waited_ < kSettleIterations) return q;
      // A ring let go off its target post is grasped again once the jaws are up and clear.
      if (!retrying_ && !restsOn(ring(scene), jobs_[job_].to, layout_.geometry)) {
        decideToRegrasp("landed off its target post");
      }
      advance(Phase::Retreat);
      return q;
    case Phase::Retreat:
      return retreat(target);
    case Phase::Done:
      return q;
  }
  return q;
}

namespace {

/// Per phase, the step of a transfer an onlooker tells apart: getting over the grasp (0),
/// gripping (1: at the grasp, closing, lifting), carrying (2), letting go (3), done (4). Within
/// one, only the routine's own memory (its waits) says where it is.
constexpr std::array<int, 11> kStage{0, 0, 1, 1, 1, 2, 2, 3, 3, 3, 4};

int stageOf(Phase phase) {
  return kStage[static_cast<std::size_t>(phase)];
}

}  // namespace

void ArmRoutine::resume(const raven::ArmJoints& target, const bridge::ScenePerception& scene) {
  std::size_t job = 0;
  while (job < jobs_.size() && restsOn(RingView(scene.sight(jobs_[job].ring), layout_.ring),
                                       jobs_[job].to, layout_.geometry)) {
    ++job;
  }
  if (job == jobs_.size()) {
    job_ = job;
    advance(Phase::Done);
    return;
  }
  // The same ring past its orientation: its grasp stays where it was planned.
  const bool planned = job == job_ && phase_ != Phase::Orient && phase_ != Phase::Done;
  job_ = job;
  const TakenUp shown = shownStep(target, scene, planned);
  // The state shows the step it is in or the one it moves on to by itself, or it is letting
  // go to grasp again (its own judgement of what it saw): it goes on as it was.
  const int stage = stageOf(phase_), shown_stage = stageOf(shown.phase);
  const bool regrasping = retrying_ && stage == stageOf(Phase::Open);
  if (planned && (shown_stage == stage || shown_stage == stage + 1 || regrasping)) return;
  spdlog::debug("{} arm: takes up {} at {} (it was at {})", raven::armName(arm_), jobs_[job_].ring,
                phaseName(shown.phase), phaseName(phase_));
  grasp_ = shown.grasp;
  retrying_ = shown.retrying;
  inner_ = target(raven::kJaw1);
  outer_ = target(raven::kJaw2);
  advance(shown.phase);
}

ArmRoutine::TakenUp ArmRoutine::shownStep(const raven::ArmJoints& target,
                                          const bridge::ScenePerception& scene,
                                          bool planned) const {
  const RingView seen = ring(scene);
  const RingJob& job = jobs_[job_];
  const Eigen::Vector3d tool = kinematics_.toolPose(target).translation();
  const bool jaws_open = target(raven::kJaw2) >= kOpen - kJawStep;
  TakenUp out{Phase::Orient, grasp_, false};
  if (!jaws_open && ringFollows(scene)) {  // in the jaws: carried from where it hangs
    out.grasp.pivot.z() = layout_.geometry.board_top + 2.0 * layout_.ring.half_height + kAboveTop;
    out.grasp.offset = out.grasp.lifted_offset = tool.head<2>() - seen.centre().head<2>();
    out.phase = (seen.centre().head<2>() - job.to).norm() < kCentred ? Phase::Lower : Phase::Carry;
    return out;
  }
  if (!planned) out.grasp = graspOn(seen, regrasps_[job_] > 0 ? graspSide(seen) : kAwayFromTargets);
  // An onlooker's tolerances: twice what the routine itself allows (its own corrections and
  // what another driver adds to the commands).
  const double near = 2.0 * kAlignReach;
  const Eigen::Vector3d from_grasp = tool - out.grasp.pivot;
  const bool over_and_low = from_grasp.head<2>().norm() <= near && from_grasp.z() >= -near;
  const bool at_grasp = from_grasp.norm() <= near;
  if (!jaws_open && seen.threadedOn(job.to)) {
    out.phase = Phase::Open;  // lowered: let it go
  } else if (jaws_open && over_and_low && from_grasp.z() <= kApproach + kStep) {
    out.phase = at_grasp ? Phase::Align : Phase::Descend;
  } else if (!jaws_open && over_and_low && from_grasp.z() <= kLift + kStep) {
    out.phase = at_grasp ? Phase::Close : Phase::Lift;  // gripping
  } else if (from_grasp.z() < kRetreat - near) {
    // Low beside the ring, or jaws shut on nothing: up first, then over it.
    out.phase = jaws_open ? Phase::Retreat : Phase::Open;
    out.retrying = true;
  }  // else high: over the ring from there (Orient)
  return out;
}

raven::ArmJoints ArmRoutine::orient(const raven::ArmJoints& target,
                                    const bridge::ScenePerception& scene) {
  // One capped move: over the ring, jaws down and open. A first grasp comes from the side away
  // from the target row; a failed grasp has often pushed the ring against its post, so a
  // re-grasp takes the side with the most room for the inner jaw (or, out of reach, the first
  // side again). Taking the roomiest side on every grasp placed all six in only 9 of seeds 1-20
  // on the motor twin (three amplifier e-stops, rings out of reach); why is not yet known.
  inner_ = 0.0;
  outer_ = kOpen;
  const RingView seen = ring(scene);
  std::vector<Eigen::Vector2d> sides{kAwayFromTargets};
  if (const Eigen::Vector2d roomiest = graspSide(seen);
      regrasps_[job_] > 0 && roomiest != kAwayFromTargets)
    sides.insert(sides.begin(), roomiest);
  for (const Eigen::Vector2d& side : sides) {
    grasp_ = graspOn(seen, side);
    if (const auto above = overRing(target)) {
      advance(Phase::Descend);
      return *above;
    }
  }
  // Out of reach: leave this ring (its outcome shows it).
  spdlog::warn("{} arm: no joint solution within the limits over {}; skipping it",
               raven::armName(arm_), jobs_[job_].ring);
  retrying_ = false;
  advance(Phase::Retreat);
  return target;
}

raven::ArmJoints ArmRoutine::align(const raven::ArmJoints& target,
                                   const raven::ArmJoints& measured) {
  // The command to the grasp; once the tool stops, on by half its lack.
  const Eigen::Vector3d tool = kinematics_.toolPose(measured).translation();
  const Eigen::Vector3d lack = grasp_.pivot - tool;
  const bool first = waited_++ == 0;
  const bool still = !first && (tool - last_tool_).norm() <= kStill;
  last_tool_ = tool;
  if (waited_ > kAlignIterations || (still && lack.norm() <= kAligned)) {
    advance(Phase::Close);
    return target;
  }
  bool arrived = false;
  if (first) return translate(target, grasp_.pivot, kStep, arrived);
  if (!still) return target;
  const raven::ArmJoints q =
      translate(target, kinematics_.toolPose(target).translation() + 0.5 * lack, kStep, arrived);
  if ((kinematics_.toolPose(q).translation() - grasp_.pivot).norm() <= kAlignReach) return q;
  spdlog::debug("{} arm, {}: something holds the tool {:.1f} mm from the grasp; closing there",
                raven::armName(arm_), jobs_[job_].ring, lack.norm() * 1e3);
  advance(Phase::Close);
  return target;
}

raven::ArmJoints ArmRoutine::carry(const raven::ArmJoints& target,
                                   const bridge::ScenePerception& scene) {
  // Over the target post, watching the ring (it sways on its grasp).
  const RingView seen = ring(scene);
  const Eigen::Vector3d tool = kinematics_.toolPose(target).translation();
  // A ring that came along is centred by sight; without one the jaws go where it would be.
  const bool carried = layout_.geometry.offTheBoard(seen.bottom());
  if (!carried && decideToRegrasp("slipped out of the jaws on the way")) {
    advance(Phase::Open);
    return target;
  }
  Eigen::Vector2d offset =
      carried ? Eigen::Vector2d(tool.head<2>() - seen.centre().head<2>()) : grasp_.offset;
  if (carried && (offset - grasp_.lifted_offset).norm() > kCarriedStray) {
    if (decideToRegrasp("does not follow the jaws")) {
      advance(Phase::Open);
      return target;
    }
    offset = grasp_.lifted_offset;  // no re-grasp left: carry on where it hung when lifted
  }
  const Eigen::Vector2d over = jobs_[job_].to + offset;
  bool arrived = false;
  const raven::ArmJoints q = translate(
      target, Eigen::Vector3d(over.x(), over.y(), grasp_.pivot.z() + kLift), kStep, arrived);
  const bool centred = !carried || (seen.centre().head<2>() - jobs_[job_].to).norm() < kCentred;
  if (arrived && (centred || ++waited_ > kCentringIterations)) advance(Phase::Lower);
  return q;
}

raven::ArmJoints ArmRoutine::lower(const raven::ArmJoints& target,
                                   const bridge::ScenePerception& scene) {
  // Down until the ring is just above the board, still centring it.
  const RingView seen = ring(scene);
  const double drop = seen.bottom() - (layout_.geometry.board_top + kReleaseHeight);
  if (!layout_.geometry.offTheBoard(seen.bottom())) {  // it did not come along
    advance(Phase::Open);
    return target;
  }
  const Eigen::Vector3d tool = kinematics_.toolPose(target).translation();
  const Eigen::Vector2d shift = jobs_[job_].to - seen.centre().head<2>();
  bool arrived = false;
  const raven::ArmJoints q = translate(
      target, tool + Eigen::Vector3d(shift.x(), shift.y(), -std::max(drop, 0.0)), kStep, arrived);
  if (arrived) advance(Phase::Open);
  return q;
}

raven::ArmJoints ArmRoutine::retreat(const raven::ArmJoints& target) {
  const Eigen::Vector3d tool = kinematics_.toolPose(target).translation();
  const double height = grasp_.pivot.z() + kRetreat;
  bool arrived = false;
  const raven::ArmJoints q =
      translate(target, Eigen::Vector3d(tool.x(), tool.y(), height), kStep, arrived);
  if (!arrived) return q;
  if (!retrying_) ++job_;
  retrying_ = false;
  advance(job_ < jobs_.size() ? Phase::Orient : Phase::Done);
  return q;
}

void ArmRoutine::logTransition(Phase before, std::size_t job, const raven::ArmJoints& q,
                               const bridge::ScenePerception& scene) const {
  const RingView seen(scene.sight(jobs_[job].ring), layout_.ring);
  const Eigen::Vector3d tool = kinematics_.toolPose(q).translation();
  spdlog::debug(
      "{} arm, {}: {} -> {}; tool ({:.4f} {:.4f} {:.4f}), ring centre ({:.4f} {:.4f} "
      "{:.4f}) bottom {:.4f}",
      raven::armName(arm_), jobs_[job].ring, phaseName(before), phaseName(phase_), tool.x(),
      tool.y(), tool.z(), seen.centre().x(), seen.centre().y(), seen.centre().z(), seen.bottom());
}

}  // namespace scenario
