#pragma once
// The paper's controller core: one set of joint targets, interpolated under the velocity caps and
// sent identically to every selected platform (the twin, the physical robot, or both in step).
// Modes O1 (homing), O2/O3 (manual: a live pad or replayed inputs), O4 (joint replay) and O5
// (sine dance) each produce targets; execute() turns them into commands.

#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bridge/raven_platform.hpp"
#include "controller/arrival.hpp"
#include "controller/following_limit.hpp"
#include "controller/gamepad_mapping.hpp"
#include "controller/velocity_cap.hpp"

namespace controller {

/// How commands reach a platform: the physical robot (and this project's twin) take servo_jr
/// increments; AMBF's model is set to absolute joint positions each step.
enum class CommandStyle { ServoJr, ServoJp };

/// One platform the controller drives.
struct PlatformSlot {
  std::string name;  ///< "twin", "physical", ...: for logs and file names
  bridge::RavenPlatform* platform = nullptr;
  CommandStyle style = CommandStyle::ServoJr;
};

/// The controller's settings.
struct ControllerOptions {
  double rate = 500.0;  ///< command steps per second (the paper: 500; 1000 possible)
  /// The controller's kinematics and home (section B of the kinematics reference).
  std::string profile = "physical";
  MappingScheme scheme = MappingScheme::M2;
  VelocityCaps caps;
  MappingConstants mapping;
  /// Platform time each manual-loop iteration takes besides its command steps: 0 for this
  /// controller; the paper's released controller took 1 ms (its recordings' rows are 2 ms per
  /// step + 1 ms apart), which replays of its recordings reproduce (raven_calibrate measures it).
  double iteration_overhead = 0.0;
  /// Scripted moves (moveTo, moveFor) keep to this, per joint: a joint whose reference robot's
  /// setpoint leads its measured position past `lead` is not advanced further that way, and one
  /// whose control-law torque is past `torque` is drawn back (an arm held back by contact is not
  /// pushed on until its amplifiers e-stop); moves that take the lead back, and the other joints
  /// of both arms, go on.
  /// None: they never stop (the paper's controller).
  std::optional<FollowingLimit> following_limit;
  /// moveTo waits at its end until each arm has arrived (or stopped where it goes), making a
  /// stopped arm's shortfall up within its bounds. None: a move ends with its last command.
  std::optional<Arrival> arrival;
};

/// What one iteration did.
struct IterationReport {
  int steps = 0;            ///< commands sent (each followed by 1/rate s, or less when cut)
  bool cut_short = false;   ///< a new pad reading ended a manual iteration early
  bool capped = false;      ///< the velocity caps stretched the move past man_steps
  bool clamped = false;     ///< a target hit a joint limit (the pad rumbles)
  bool held_back = false;   ///< a joint of a scripted move held at the following limit
  std::size_t refused = 0;  ///< commands a platform refused
  std::string refusal;      ///< the first refusal's reason
};

/// The O5 sine dance's constants (the reference's), per joint in ArmJoints order.
struct SineDance {
  raven::ArmJoints scale =
      (raven::ArmJoints() << 0.3, 0.3, 0.06, 0.3, 1.2, M_PI / 6.0, M_PI / 6.0).finished();
  double speed = 10.0 / 500.0;  ///< phase per call
  double ramp_per_call = 0.5 / 500.0;
};

/// The live pad, read after every command period of a manual iteration (empty: unplugged).
using LivePad = std::function<std::optional<recording::GamepadState>()>;

/// Sends one target stream to every platform. Not thread-safe: one command thread owns it.
class DualPlatformController {
 public:
  /// The first platform is the reference: its measured joints start the targets.
  DualPlatformController(std::vector<PlatformSlot> platforms, ControllerOptions options);

  /// Re-reads the pose from the reference platform's measured joints.
  void readPose();
  /// The next manual iteration sends `change` from where the arms' setpoints stand, whatever
  /// its own targets were: the first move a recording shows its controller made (firstMoveOf),
  /// for a replay from that recording's start. The targets then go on from the mapping's.
  void sendFirstMove(const ArmPair& change) { first_move_ = change; }
  /// O1: from the current targets to the controller's home under the caps, then the stored
  /// wrist values are reset.
  IterationReport home();
  /// O2 / O3: one manual-loop iteration from a pad reading: the mapping's move, split under
  /// the caps into at least man_steps command steps. With `live`, the pad is read again after
  /// every robot cycle (1 ms; twice a period at 500 Hz), and a reading that differs from `pad`
  /// ends the iteration there (the targets where its interpolation got to): the next
  /// iteration starts at once from it, its first command carrying only the share of a step
  /// that the time since the last command allows. A steady pad runs whole iterations as
  /// without `live`.
  IterationReport manual(const recording::GamepadState& pad, const LivePad& live = {});
  /// O4: one recorded joint row, reached under the caps; then the platforms' clocks run on to
  /// `due` seconds after the replay began (the recording's own timing).
  IterationReport replayJoints(const ArmPair& joints, double due);
  /// O5: one call of the sine dance (every platform, within the caps and the limits).
  IterationReport sineDance();
  /// Starts a mode's clock: the sine dance's count and the joint replay's start time.
  void beginMode();
  /// Lets one command period pass on every platform without moving.
  void idle();
  /// Scripted operation: moves every platform to `joints` under the caps (C_V), as a pad's
  /// iteration would; the mapping then continues from there.
  IterationReport moveTo(const ArmPair& joints);
  /// Scripted operation for exactly `steps` command periods: towards `joints` under the caps;
  /// a move that needs fewer steps arrives and holds, one that needs more stops where its
  /// interpolation is after `steps` (the targets are then that point, not `joints`).
  IterationReport moveFor(const ArmPair& joints, int steps);

  /// The largest difference between the first two platforms' measured joints (0 with one).
  double divergence() const;
  const ArmPair& commanded() const { return commanded_; }
  const GamepadMapping& mapping() const { return mapping_; }
  const std::vector<PlatformSlot>& platforms() const { return platforms_; }
  double period() const { return 1.0 / options_.rate; }

  /// What its next iterations depend on: the targets, the mapping's, the mode's clock (the
  /// learning environment's snapshots).
  struct State {
    ArmPair commanded;
    GamepadMapping mapping;
    long dance_count;
    double mode_start;
    double since_command;
    std::optional<ArmPair> first_move;
  };
  State state() const {
    return {commanded_, mapping_, dance_count_, mode_start_, since_command_, first_move_};
  }
  void restore(const State& state) {
    first_move_ = state.first_move;
    commanded_ = state.commanded;
    mapping_ = state.mapping;
    dance_count_ = state.dance_count;
    mode_start_ = state.mode_start;
    since_command_ = state.since_command;
  }

 private:
  /// C_V: moves every platform from the current targets to `next` in capped steps, at most
  /// `most` of them, ending early once `stop` says so after a step (the targets are then where
  /// the interpolation got to). A stop mid-period ends the period there.
  /// `stop`: asked between cycles, ends the move there (cut short); `following`: before each
  /// command, the joints at the following limit stop there (held back), the others go on, and
  /// the move ends once none is left to move; `first_jump`: added to the first command's
  /// increments (a setpoint moved off the targets).
  IterationReport execute(const ArmPair& next, int most = std::numeric_limits<int>::max(),
                          const std::function<bool()>& stop = {}, bool following = false,
                          const ArmPair* first_jump = nullptr);
  /// Sends command k of `plan` to every platform, its increments moved by `jump`.
  void send(const InterpolationPlan& plan, int k, IterationReport& report, const ArmPair& jump);
  /// One command period on every platform; with `stop`, in robot cycles, asking it after each
  /// (but the last of a `final` period): true when it said stop, the period cut there.
  bool waitPeriod(const std::function<bool()>& stop, bool final);
  /// Robot cycles in one command period (at least one).
  int cyclesPerPeriod() const;
  /// Lets `seconds` pass on every platform.
  void advanceAll(double seconds);
  /// One command period at the targets, the setpoints moved by `make_up` if given; under a
  /// following limit a joint past its torque's is drawn back meanwhile.
  IterationReport holdStill(const ArmPair* make_up = nullptr);
  /// moveTo's end under an arrival: holds the targets (holdStill), each time an arm's wrist has
  /// stopped short moving its shoulder's, elbow's and insertion's setpoints on by half the
  /// shortfall (within the bound, a capped step a period), until every joint has arrived or
  /// stopped, for at most the longest wait.
  void arrive(IterationReport& report);
  /// moveTo / moveFor: clamped to the limits, at most `most` steps, the mapping following.
  IterationReport scriptedMove(const ArmPair& joints, int most);
  ArmPair measured(const PlatformSlot& slot) const;
  /// From command `done` of `plan` on, stops each joint whose reference robot's setpoint leads
  /// its measured position past the following limit in the direction the plan still moves it, and
  /// holds each joint whose torque is past its limit drawn back (by `jump`, for the next command)
  /// where the plan would push on; whether it held any.
  bool holdAtFollowingLimit(InterpolationPlan& plan, int done, ArmPair& jump) const;
  void clamp(ArmPair& joints, IterationReport& report) const;

  std::vector<PlatformSlot> platforms_;
  ControllerOptions options_;
  raven::PlatformProfile profile_;
  ArmPair commanded_;
  std::optional<ArmPair> first_move_;  ///< sendFirstMove's, until the next manual iteration
  GamepadMapping mapping_;
  SineDance dance_;
  long dance_count_ = 0;
  double mode_start_ = 0.0;
  /// Platform time since the last command (a period or more: the next may carry a whole step).
  double since_command_ = std::numeric_limits<double>::infinity();
};

}  // namespace controller
