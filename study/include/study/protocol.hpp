#pragma once
// A study's protocol, read from YAML: the tasks, the conditions (mapping scheme and the
// controller's settings), the repetitions, rests, counterbalancing, questionnaires and the
// tuning block. Every bad value is refused naming the file, line and key.

#include <Eigen/Core>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "controller/dual_platform_controller.hpp"
#include "study/questionnaire.hpp"

namespace study {

/// What a task asks of the arms.
enum class TaskKind {
  Targets,     ///< reach points with the tool tips (random, the rectangle D_II, or listed)
  PegTransfer  ///< the peg-transfer scene: six rings onto their target posts
};

/// One task of the protocol.
struct TaskSpec {
  std::string name;
  TaskKind kind = TaskKind::Targets;
  std::string instructions;  ///< shown before each trial
  double time_limit = 60.0;  ///< s; a trial that reaches it is ended and marked not completed
  /// Trials of this task per condition (none: the protocol's trials_per_condition); a task done
  /// fewer times than the others takes the condition's last repetitions, after the practice.
  std::optional<int> trials;
  /// s: the FLS-style bar the report counts trials and participants against (finished within
  /// it; twice in a row), when the protocol states one.
  std::optional<double> proficiency_time;
  /// N: a jaw pressing on anything harder than this is excessive force. 3 N pinches bowel
  /// against a 5 N pull (../shared/reference/soft-materials.md); a ring needs far less.
  double excessive_force = 3.0;
  // Targets only. Per arm, each target is relative to the arm's homed tool tip (controller
  // frame, m); arms with no targets hold still.
  std::string pattern = "random";            ///< "random", "rectangle" or "list"
  int count = 4;                             ///< random: targets per arm
  double distance = 0.015;                   ///< random: each target this far from the start point
  double height = 0.005;                     ///< random: up to this far above or below it
  double width = 0.03, depth = 0.02;         ///< rectangle (D_II), both arms alike
  std::vector<Eigen::Vector3d> left, right;  ///< list
  double tolerance = 0.003;                  ///< m: inside counts as on the target
  double dwell = 0.3;                        ///< s held inside to reach it
};

/// One condition: the mapping scheme and the controller settings a participant works with.
struct Condition {
  std::string name;
  /// "m2", "m1" (one arm at a time, the participant switches arms with Back / Start),
  /// "m1-left" or "m1-right" (that arm only).
  std::string scheme = "m2";
  bool full_ik = false;         ///< C_W off: the full IK (B) instead of the wrist-locked IK (A)
  double velocity_scale = 1.0;  ///< C_V: the paper's joint speed caps times this
  int man_steps = 10;           ///< C_V: the fewest command steps per manual iteration
  double deadzone = 0.15;       ///< radial, raw values past it used as they are
  double divisor = 2000.0;      ///< stick / divisor = metres per manual iteration
  double wrist_divisor = 10.0;  ///< M1: stick / wrist_divisor = rad per iteration
  double rate = 500.0;          ///< command steps per second

  /// The controller's settings for this condition (the physical profile, M2 or M1 left).
  controller::ControllerOptions controllerOptions() const;
  /// Metres per second at full stick when the caps do not bind.
  double translationGain() const { return rate / (divisor * man_steps); }
};

/// How the conditions are ordered across participants.
enum class OrderKind {
  LatinSquare,  ///< a Williams design: each condition once per position, carry-over balanced
  Fixed         ///< protocol order for everyone
};

/// Which settings the tuning block may move, within what bounds.
struct TunedParameter {
  std::string name;  ///< "velocity_scale", "divisor", "deadzone", "wrist_divisor", "man_steps"
  double low = 0.0, high = 0.0;
};

/// Between trials an optimiser proposes the next settings to try; the cost is stated.
struct TuningSpec {
  std::string condition;  ///< the base condition the tuned settings replace values of
  std::string task;       ///< the task each tuning trial runs
  std::vector<TunedParameter> parameters;
  std::map<std::string, double> cost;  ///< metric name -> weight (the cost is their sum)
  int trials = 8;
  int initial = 3;  ///< spread over the bounds before the optimiser's proposals begin

  std::string costText() const;  ///< "1 x completion_time_s + 2 x overshoots"
};

/// A whole protocol.
struct Protocol {
  std::filesystem::path file;
  std::string name;
  std::vector<TaskSpec> tasks;
  std::vector<Condition> conditions;
  int trials_per_condition = 2;  ///< each task this many times per condition
  double rest = 30.0;            ///< s between conditions (people only)
  double countdown = 3.0;        ///< s before each trial (people only)
  OrderKind order = OrderKind::LatinSquare;
  std::vector<QuestionnaireForm> questionnaires;  ///< asked after each condition, in order
  std::optional<TuningSpec> tuning;
  std::string text;  ///< the file's bytes: a resumed session refuses a changed protocol

  const TaskSpec& task(const std::string& named) const;
  const Condition& condition(const std::string& named) const;
};

/// Reads and checks a protocol. Throws common::LoadError naming the file, line and key.
Protocol loadProtocol(const std::filesystem::path& file);

/// `base` with the tuned settings `values` (in TuningSpec::parameters order) applied.
Condition tunedCondition(const Condition& base, const std::vector<TunedParameter>& parameters,
                         const std::vector<double>& values);

}  // namespace study
