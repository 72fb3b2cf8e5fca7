#pragma once
// A simulated person at the gamepad, for testing a protocol and planning a study's size. It
// steers the tool tips to the task's goals in intermittent submovements (Meyer et al. 1988,
// Miall et al. 1993): it sees the robot a visuomotor delay late, plans each push from what it
// believes the stick's gain is, pushes at least past the deadzone it has learnt, holds the push
// for the time the belief gives, and looks again. Its belief of the gain starts only partly
// adapted to a new mapping (the crossover model's gain adaptation, McRuer & Jex 1967,
// incomplete within a short session, improving with trials) and learns from each push's
// outcome (error-based adaptation), so a faster mapping makes it overshoot and a slower one
// undershoot until it has learnt; its idea of the deadzone starts the same way and grows each
// time a push moves nothing. Physiological tremor (8-12 Hz, Elble & Koller 1990) rides on both
// sticks and its pushes carry signal-dependent noise (Harris & Wolpert 1998). docs/study.md states
// the model and its numbers.

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <deque>
#include <nlohmann/json.hpp>
#include <random>

#include "recording/gamepad_state.hpp"
#include "study/protocol.hpp"
#include "study/trial_task.hpp"

namespace study {

/// One simulated person's constants, drawn once per participant.
struct ParticipantTraits {
  double delay = 0.22;          ///< s from the robot moving to the person seeing it
  double decision = 0.08;       ///< s to plan the next push after looking
  double move_time = 0.40;      ///< s a person aims to take for one push (when the stick allows)
  double min_push = 0.08;       ///< s: the briefest push a thumb makes
  double adaptation = 0.5;      ///< 0..1: how much of a gain change the first trial's belief takes
  double learning = 3.0;        ///< trials under a condition for the rest of it to halve
  double push_learning = 0.5;   ///< share of a push's gain error the belief takes after it
  double deflection_cv = 0.12;  ///< signal-dependent noise of a push's size (SD / mean)
  double timing_cv = 0.10;      ///< of a push's duration (Wing & Kristofferson 1973)
  double tremor = 0.015;        ///< stick deflection (fraction of full travel)
  double tremor_hz = 10.0;
  double perception = 0.0003;  ///< m: SD of where the person judges a tip to be
  double aim = 0.5;            ///< stops pushing inside this fraction of the tolerance

  /// A person drawn from the stated population (docs/study.md) by `seed`.
  static ParticipantTraits draw(std::uint64_t seed);
  nlohmann::json json() const;
};

/// What a person works with under one condition.
struct ConditionFeel {
  double gain = 0.025;            ///< m/s at full stick (Condition::translationGain)
  double reference_gain = 0.025;  ///< the paper's mapping, which the person knows best
  double deadzone = 0.15;
  double reference_deadzone = 0.15;
  std::string scheme = "m2";
  double trigger_full = 4.0;  ///< the trigger's travel: grasp = 1 - trigger / trigger_full
  int trials_before = 0;      ///< trials this person already did under this condition

  static ConditionFeel of(const Condition& condition, int trials_before);
};

/// The person's hands over one trial: call act() once per manual-loop iteration.
class VirtualParticipant {
 public:
  VirtualParticipant(const ParticipantTraits& traits, const ConditionFeel& feel,
                     std::uint64_t seed);

  /// The pad at time `t` (s), having seen `goals` and the tool tips `tips` (controller frame)
  /// now; it acts on what it saw `delay` ago. A goal's grasp is squeezed on the arm's trigger
  /// (M2: each arm's own; M1: the right one), pressed anew, with the push's noise, each time the
  /// wanted grasp changes.
  recording::GamepadState act(double t, const raven::PerArm<ArmGoal>& goals,
                              const raven::PerArm<Eigen::Vector3d>& tips);

  /// The gain the person believes `arm` moves with (m/s at full stick), horizontally or along z.
  double believedGain(int arm, bool z) const {
    return believed_[static_cast<std::size_t>(2 * arm + (z ? 1 : 0))];
  }

 private:
  struct Seen {
    double t;
    raven::PerArm<ArmGoal> goals;
    raven::PerArm<Eigen::Vector3d> tips;
  };
  /// One thumb: idle until `until`, or pushing `stick` (x, y) until `until`.
  struct Hand {
    int arm = -1;
    bool pushing = false;
    bool z_plane = false;  ///< the bumper held: the stick's y drives z
    Eigen::Vector2d stick = Eigen::Vector2d::Zero();
    double until = 0.0;
    /// The last push, to learn from when the hand looks again: where the tip was seen before
    /// it and the displacement it was meant to give (empty: nothing to learn).
    Eigen::Vector3d from = Eigen::Vector3d::Zero();
    Eigen::Vector3d meant = Eigen::Vector3d::Zero();
    double deflection = 0.0;  ///< of the last push, as meant
    /// Where the push aims, and when it began and was planned to end: a push the person sees
    /// reach its aim is let go at once.
    Eigen::Vector3d aim = Eigen::Vector3d::Zero();
    double started = 0.0, planned_until = 0.0;
  };
  /// How far an arm's trigger is pressed, and for which wanted grasp.
  struct Trigger {
    double wanted = 1.0;  ///< the trigger let go
    double value = 0.0;
  };
  const Seen& seen(double t) const;
  /// Arm `arm`'s trigger for the grasp `goal` wants.
  double squeeze(int arm, const ArmGoal& goal);
  /// Plans the next push of `hand` for arm `arm` from what was seen.
  void plan(Hand& hand, int arm, const Seen& view, double t);
  /// Ends a push early once `view` shows the tip about to reach its aim along the push (a long
  /// move is watched, not timed blind), not following it, or the aim moved; what it was meant to
  /// do shrinks to the time it lasted.
  void watch(Hand& hand, const Seen& view, double t) const;
  Eigen::Vector2d tremor(double t, int hand) const;

  ParticipantTraits traits_;
  ConditionFeel feel_;
  std::array<double, 4> believed_;  ///< per arm: horizontal, z
  double believed_deadzone_;        ///< the stick travel it thinks does nothing
  std::mt19937_64 rng_;
  std::deque<Seen> history_;
  raven::PerArm<Hand> hands_;
  raven::PerArm<Trigger> triggers_;
  int selected_arm_ = 0;           ///< M1: the arm the left stick drives
  double selecting_until_ = -1.0;  ///< M1: a Back / Start press in progress
  std::array<double, 4> tremor_phase_{};
};

}  // namespace study
