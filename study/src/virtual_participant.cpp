#include "study/virtual_participant.hpp"

#include <algorithm>
#include <cmath>

namespace study {

namespace {

/// s over which the person judges how fast the tip moves.
constexpr double kSpeedWindow = 0.1;
/// A push whose tip is seen going slower than this share of the meant speed is not followed: a
/// halving, far above what a person tells apart (speeds differing by about 10 %, McKee 1981), so
/// the ordinary lag of a tool that starts or slows does not count.
constexpr double kStalled = 0.5;

/// A normal draw clipped to [low, high].
double clipped(std::mt19937_64& rng, double mean, double sd, double low, double high) {
  return std::clamp(std::normal_distribution<double>(mean, sd)(rng), low, high);
}

}  // namespace

ParticipantTraits ParticipantTraits::draw(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  ParticipantTraits p;
  p.delay = clipped(rng, 0.22, 0.03, 0.15, 0.35);
  p.decision = clipped(rng, 0.08, 0.02, 0.04, 0.15);
  p.move_time = clipped(rng, 0.40, 0.08, 0.25, 0.70);
  p.min_push = clipped(rng, 0.08, 0.015, 0.05, 0.12);
  p.adaptation = clipped(rng, 0.5, 0.15, 0.1, 0.9);
  p.learning = clipped(rng, 3.0, 1.0, 1.0, 6.0);
  p.push_learning = clipped(rng, 0.5, 0.1, 0.2, 0.8);
  p.deflection_cv = clipped(rng, 0.12, 0.03, 0.05, 0.25);
  p.timing_cv = clipped(rng, 0.10, 0.02, 0.05, 0.20);
  p.tremor = clipped(rng, 0.015, 0.005, 0.005, 0.04);
  p.tremor_hz = std::uniform_real_distribution<double>(8.0, 12.0)(rng);
  p.perception = clipped(rng, 0.0003, 0.0001, 0.0001, 0.0008);
  return p;
}

nlohmann::json ParticipantTraits::json() const {
  return {{"delay_s", delay},
          {"decision_s", decision},
          {"move_time_s", move_time},
          {"min_push_s", min_push},
          {"adaptation", adaptation},
          {"learning_trials", learning},
          {"push_learning", push_learning},
          {"deflection_cv", deflection_cv},
          {"timing_cv", timing_cv},
          {"tremor", tremor},
          {"tremor_hz", tremor_hz},
          {"perception_m", perception},
          {"aim", aim}};
}

ConditionFeel ConditionFeel::of(const Condition& condition, int trials_before) {
  ConditionFeel f;
  f.gain = condition.translationGain();
  f.deadzone = condition.deadzone;
  f.scheme = condition.scheme;
  f.trigger_full = condition.controllerOptions().mapping.trigger_full;
  f.trials_before = trials_before;
  return f;
}

VirtualParticipant::VirtualParticipant(const ParticipantTraits& traits, const ConditionFeel& feel,
                                       std::uint64_t seed)
    : traits_(traits), feel_(feel), rng_(seed) {
  // The belief moves from the known gain towards the true one: a share `adaptation` at once,
  // then half of what is left every `learning` trials.
  const double left = (1.0 - traits.adaptation) * std::exp2(-feel.trials_before / traits.learning);
  believed_.fill(std::pow(feel.reference_gain, left) * std::pow(feel.gain, 1.0 - left));
  believed_deadzone_ = left * feel.reference_deadzone + (1.0 - left) * feel.deadzone;
  std::uniform_real_distribution<double> phase(0.0, 2.0 * M_PI);
  for (double& p : tremor_phase_) p = phase(rng_);
  if (feel.scheme == "m1-right") selected_arm_ = 1;
}

const VirtualParticipant::Seen& VirtualParticipant::seen(double t) const {
  const Seen* out = &history_.front();
  for (const Seen& s : history_) {
    if (s.t <= t) out = &s;
  }
  return *out;
}

void VirtualParticipant::watch(Hand& hand, const Seen& view, double t) const {
  if (!hand.pushing || t >= hand.until || hand.meant.norm() == 0.0) return;
  // How far the tip still has to go along the push, and how fast it was seen to go: the person
  // lets go once what is left is what the tip covers in one visuomotor delay (an internal model
  // of its own delay, Miall et al. 1993), so a long push stops on its aim, not past it.
  const auto arm = static_cast<std::size_t>(hand.arm);
  const Eigen::Vector3d along = hand.meant.normalized();
  const Seen& before = seen(view.t - kSpeedWindow);
  const double left = (hand.aim - view.tips[arm]).dot(along);
  const double speed = view.t > before.t
                           ? (view.tips[arm] - before.tips[arm]).dot(along) / (view.t - before.t)
                           : 0.0;
  // A push the tip is seen not to follow once it had time to show (the tool held by a post,
  // the ring, the board; a stick inside the deadzone) is let go too: pushing on moves only the
  // command, and the robot's controller would wind up against what holds the tool.
  const double meant_speed = hand.meant.norm() / (hand.planned_until - hand.started);
  const bool stalled = before.t >= hand.started + kSpeedWindow && speed < kStalled * meant_speed &&
                       left > traits_.perception;
  // And one whose aim the person sees moved (a new target, a step that asks for something else).
  const ArmGoal& goal = view.goals[arm];
  const bool aim_moved = !goal.active || (goal.point - hand.aim).norm() > goal.tolerance;
  if (!stalled && !aim_moved && left > std::max(speed, 0.0) * traits_.delay) return;
  hand.meant *= (t - hand.started) / (hand.planned_until - hand.started);
  hand.until = t;
}

double VirtualParticipant::squeeze(int arm, const ArmGoal& goal) {
  Trigger& trigger = triggers_[static_cast<std::size_t>(arm)];
  const double wanted = goal.active ? goal.grasp : 1.0;
  if (wanted != trigger.wanted) {
    trigger.wanted = wanted;
    const double press = std::max(0.0, 1.0 - wanted) * feel_.trigger_full;
    const double noise = 1.0 + traits_.deflection_cv * std::normal_distribution<double>()(rng_);
    trigger.value = std::clamp(press * noise, 0.0, 0.999 * feel_.trigger_full);
  }
  return trigger.value;
}

Eigen::Vector2d VirtualParticipant::tremor(double t, int hand) const {
  const double w = 2.0 * M_PI * traits_.tremor_hz * t;
  const auto h = static_cast<std::size_t>(2 * hand);
  return traits_.tremor *
         Eigen::Vector2d(std::sin(w + tremor_phase_[h]), std::sin(w + tremor_phase_[h + 1]));
}

void VirtualParticipant::plan(Hand& hand, int arm, const Seen& view, double t) {
  if (hand.arm != arm) hand.meant.setZero();  // M1 switched arms: nothing to learn from
  hand.arm = arm;
  hand.pushing = false;
  hand.until = t + traits_.decision;
  const ArmGoal& goal = view.goals[static_cast<std::size_t>(arm)];
  if (!goal.active) return;
  std::normal_distribution<double> unit(0.0, 1.0);
  const Eigen::Vector3d judged =
      view.tips[static_cast<std::size_t>(arm)] +
      traits_.perception * Eigen::Vector3d(unit(rng_), unit(rng_), unit(rng_));
  // What the last push did against what it was meant to do: the belief takes part of the
  // difference.
  if (hand.meant.norm() > 0.0005) {
    const Eigen::Vector3d along = hand.meant.normalized();
    const double moved = (judged - hand.from).dot(along) / hand.meant.norm();
    if (moved < 0.1 && hand.deflection < 1.0) {  // nothing moved: the deadzone is wider
      believed_deadzone_ = std::max(believed_deadzone_, hand.deflection);
    } else {
      double& belief = believed_[static_cast<std::size_t>(2 * arm + (hand.z_plane ? 1 : 0))];
      belief *= std::pow(std::clamp(moved, 0.2, 5.0), traits_.push_learning);
    }
  }
  hand.meant.setZero();
  const Eigen::Vector3d e = goal.point - judged;
  if (e.norm() <= traits_.aim * goal.tolerance) return;  // on target: hold still
  // One push in one plane: the horizontal one, or z with the bumper held.
  hand.z_plane = std::abs(e.z()) > e.head<2>().norm();
  const Eigen::Vector2d d =
      hand.z_plane ? Eigen::Vector2d(0.0, e.z()) : Eigen::Vector2d(e.head<2>());
  const double distance = d.norm();
  const double gain = believedGain(arm, hand.z_plane);
  // Past the deadzone it believes in (a little beyond it), and never beyond full travel.
  const double least = std::min(believed_deadzone_ + 0.05, 1.0);
  double deflection = std::clamp(distance / (traits_.move_time * gain), least, 1.0);
  double duration = std::max(distance / (gain * deflection), traits_.min_push);
  // What the push should give if the belief is right (past the briefest push: more than meant).
  const double expected = gain * deflection * duration;
  hand.deflection = deflection;
  deflection = std::clamp(deflection * (1.0 + traits_.deflection_cv * unit(rng_)), 0.0, 1.0);
  duration = std::max(duration * (1.0 + traits_.timing_cv * unit(rng_)), 0.02);
  const Eigen::Vector2d along = d / distance * deflection;
  // Stick sense: x right; y down when pushed forward (M2: dy = -y, with the bumper dz = -y).
  hand.stick = Eigen::Vector2d(along.x(), -along.y());
  hand.pushing = true;
  hand.until = t + duration;
  hand.started = t;
  hand.planned_until = hand.until;
  hand.aim = goal.point;
  hand.from = judged;
  hand.meant =
      (hand.z_plane ? Eigen::Vector3d(0.0, 0.0, d.y()) : Eigen::Vector3d(d.x(), d.y(), 0.0)) *
      (expected / distance);
}

recording::GamepadState VirtualParticipant::act(double t, const raven::PerArm<ArmGoal>& goals,
                                                const raven::PerArm<Eigen::Vector3d>& tips) {
  history_.push_back({t, goals, tips});
  while (history_.size() > 2 && history_[1].t <= t - traits_.delay - kSpeedWindow) {
    history_.pop_front();
  }
  const Seen& view = seen(t - traits_.delay);

  recording::GamepadState pad;
  const bool one_at_a_time = feel_.scheme == "m1";
  // M1 with both arms to do: when the selected arm is done, select the other (Back: left,
  // Start: right), then look again.
  if (one_at_a_time && t >= selecting_until_ && !hands_[0].pushing) {
    const int other = 1 - selected_arm_;
    if (!view.goals[static_cast<std::size_t>(selected_arm_)].active &&
        view.goals[static_cast<std::size_t>(other)].active) {
      selected_arm_ = other;
      selecting_until_ = t + 0.1;
      hands_[0].until = selecting_until_ + traits_.delay + traits_.decision;
    }
  }
  if (t < selecting_until_) (selected_arm_ == 0 ? pad.back : pad.start) = true;

  const bool m2 = feel_.scheme == "m2";
  for (int h = 0; h < (m2 ? 2 : 1); ++h) {
    Hand& hand = hands_[static_cast<std::size_t>(h)];
    const int arm = m2 ? h : selected_arm_;
    watch(hand, view, t);
    if (hand.pushing && t >= hand.until) {  // let go, then look at where it went
      hand.pushing = false;
      hand.until = t + traits_.delay + traits_.decision;
    } else if (!hand.pushing && t >= hand.until) {
      plan(hand, arm, view, t);
    }
  }
  const auto stick = [&](int h) {
    const Hand& hand = hands_[static_cast<std::size_t>(h)];
    const Eigen::Vector2d s = (hand.pushing ? hand.stick : Eigen::Vector2d::Zero()) + tremor(t, h);
    return Eigen::Vector2d(std::clamp(s.x(), -1.0, 1.0), std::clamp(s.y(), -1.0, 1.0));
  };
  const Eigen::Vector2d left = stick(0), right = stick(1);
  pad.left_x = left.x();
  pad.left_y = left.y();
  pad.left_bumper = hands_[0].pushing && hands_[0].z_plane;
  pad.right_x = right.x();
  pad.right_y = right.y();
  pad.right_bumper = m2 && hands_[1].pushing && hands_[1].z_plane;
  if (m2) {
    pad.left_trigger = squeeze(0, view.goals[0]);
    pad.right_trigger = squeeze(1, view.goals[1]);
  } else {
    pad.right_trigger = squeeze(selected_arm_, view.goals[static_cast<std::size_t>(selected_arm_)]);
  }
  return pad;
}

}  // namespace study
