// raven_controller: the dual-platform controller. One instance drives the twin, the physical
// Raven-II, or both in step, from a gamepad, the keyboard's mode keys, or a recorded file.

#include <spdlog/spdlog.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <atomic>
#include <csignal>
#include <map>
#include <memory>
#include <optional>

#include "bridge/enable_and_home.hpp"
#include "bridge/ros/master_watch.hpp"
#include "bridge/ros/raven_ros_client.hpp"
#include "bridge/ros/ros_runtime.hpp"
#include "common/actuation_flag.hpp"
#include "common/number_checks.hpp"
#include "controller/first_move.hpp"
#include "controller/session.hpp"
#include "controller/terminal_keys.hpp"
#include "in_process_twin.hpp"
#include "raven/control_cycle.hpp"

namespace {

std::atomic<bool> interrupted{false};

using controller::Mode;

/// Command-line settings.
struct Settings {
  std::string platform = "twin";
  bool twin_over_ros = false;
  std::string twin_ns = "/twin";
  std::string physical_ns;
  common::ActuationKind actuation = common::ActuationKind::Motors;  ///< of the in-process twin
  std::string start_from;
  std::string calibration_file;
  std::string twin_launch;
  common::VideoFlags video;  ///< of the in-process twin
  bool lock_step = false;
  bool no_arm_swap = false;
  std::string start_mode;
  std::string replay_ci, replay_rs;
  std::string record = "no";   ///< from the start: yes or no (the r key records either way)
  std::string name = "raven";  ///< the recordings' file prefix
  std::string out_dir = "recordings";
  std::string mapping = "m2";
  std::string trigger_range = "xbox-one";
  bool paper_deadzone = false;
  bool no_gamepad = false, no_keyboard = false;
  double duration = 0.0;
  double rate = 500.0;
  int man_steps = 10;
  double deadzone = 0.15, divisor = 2000.0, wrist_divisor = 10.0;
  double velocity_scale = 1.0;
};

/// Owns whichever platforms the settings ask for.
struct Platforms {
  std::unique_ptr<bridge::RavenPlatform> twin;
  std::vector<std::unique_ptr<bridge::ros1::RavenRosClient>> clients;
  std::vector<controller::PlatformSlot> slots;
};

/// `calibration`: the loaded --calibration profile, or null; `start_from`: the --start-from
/// recording, or null.
Platforms makePlatforms(const Settings& s, const controller_app::ControllerCalibration* calibration,
                        const recording::RsRecording* start_from) {
  Platforms p;
  const bool want_physical = s.platform != "twin";
  const bool want_twin = s.platform != "physical";
  if (!s.video.file.empty() && (!want_twin || s.twin_over_ros)) {
    throw std::runtime_error(
        "--video records the in-process twin (not --platform physical, not --twin-over-ros)");
  }
  if (want_physical) {
    bridge::ros1::RosClientOptions o;
    o.robot_namespace = s.physical_ns;
    o.arm_swap = !s.no_arm_swap;
    p.clients.push_back(std::make_unique<bridge::ros1::RavenRosClient>(o));
    p.slots.push_back({"physical", p.clients.back().get(), controller::CommandStyle::ServoJr});
  }
  if (want_twin && s.twin_over_ros) {
    bridge::ros1::RosClientOptions o;
    o.robot_namespace = s.twin_ns;
    o.lock_step = s.lock_step;
    p.clients.push_back(std::make_unique<bridge::ros1::RavenRosClient>(o));
    p.slots.push_back({"twin", p.clients.back().get(), controller::CommandStyle::ServoJr});
  } else if (want_twin) {
    p.twin = controller_app::makeInProcessTwin(
        {s.twin_launch, s.lock_step, s.actuation, calibration, s.video, start_from});
    p.slots.push_back({"twin", p.twin.get(), controller::CommandStyle::ServoJr});
  }
  return p;
}

/// Enables and homes every platform that is not ready yet (at most 30 s of platform time).
void makeReady(const std::vector<controller::PlatformSlot>& slots) {
  for (const auto& slot : slots) {
    if (slot.platform->operatingStatus().ready()) continue;
    spdlog::info("{}: enabling and homing", slot.name);
    try {
      bridge::enableAndHome(*slot.platform, 30.0, [] { return !interrupted; });
    } catch (const std::runtime_error& e) {
      throw std::runtime_error(slot.name + " " + e.what());
    }
  }
}

std::optional<Mode> modeFromKey(char key) {
  static const std::map<char, Mode> keys{{'1', Mode::Homing},
                                         {'2', Mode::Manual},
                                         {'3', Mode::ReplayInputs},
                                         {'4', Mode::ReplayJoints},
                                         {'5', Mode::SineDance}};
  const auto it = keys.find(key);
  return it == keys.end() ? std::nullopt : std::optional<Mode>(it->second);
}

/// Refuses settings that do not go together, before anything is read or moves.
void checkSettings(const Settings& s) {
  if (!s.start_from.empty() && (s.platform != "twin" || s.twin_over_ros)) {
    throw std::runtime_error("--start-from places the in-process twin (--platform twin only)");
  }
  if (s.velocity_scale > 1.0 && s.platform != "twin") {
    throw std::runtime_error(
        "--velocity-scale above 1 raises the paper's joint speed caps: the "
        "twin only, never the physical robot");
  }
  if (s.lock_step && s.platform != "twin") {
    throw std::runtime_error(
        "--lock-step drives the twin alone; the physical robot runs in real time");
  }
  if (s.lock_step && s.replay_ci.empty() && s.replay_rs.empty() && s.start_mode != "o5" &&
      s.start_mode != "o1") {
    throw std::runtime_error(
        "--lock-step needs a replay (--replay-ci / --replay-rs) or --mode o1/o5");
  }
}

controller::ControllerOptions controllerOptions(
    const Settings& s, const std::optional<controller_app::ControllerCalibration>& calibration) {
  controller::ControllerOptions options;
  options.rate = s.rate;
  options.caps.min_steps = s.man_steps;
  options.caps.per_second *= s.velocity_scale;
  options.mapping.deadzone = s.deadzone;
  options.mapping.divisor = s.divisor;
  options.mapping.wrist_divisor = s.wrist_divisor;
  options.scheme = controller::mappingSchemeNamed(s.mapping);
  options.mapping.deadzone_reads_y_twice = s.paper_deadzone;
  if (calibration) options.iteration_overhead = calibration->iteration_overhead;
  return options;
}

/// The mode a session starts in: the one asked for, else the replay's, else manual with a pad.
Mode firstMode(const Settings& s, bool has_pad) {
  const std::map<std::string, Mode> modes{{"o1", Mode::Homing},
                                          {"o2", Mode::Manual},
                                          {"o3", Mode::ReplayInputs},
                                          {"o4", Mode::ReplayJoints},
                                          {"o5", Mode::SineDance}};
  if (!s.start_mode.empty()) return modes.at(s.start_mode);
  return !s.replay_ci.empty()   ? Mode::ReplayInputs
         : !s.replay_rs.empty() ? Mode::ReplayJoints
         : has_pad              ? Mode::Manual
                                : Mode::Idle;
}

/// Turns the session until it ends, a key quits it, the duration passes or a platform faults;
/// reports the twin's divergence from the physical robot when both run.
void turnUntilDone(controller::ControllerSession& session,
                   const controller::DualPlatformController& control,
                   const std::vector<controller::PlatformSlot>& slots,
                   controller::TerminalKeys* keys, const Settings& s) {
  auto& reference = *slots.front().platform;
  const double start = reference.now();
  double next_report = start + 1.0, worst_divergence = 0.0;
  std::size_t turns = 0;
  while (!interrupted && session.turn()) {
    ++turns;
    // One key per turn: each takes effect after at least one iteration of the previous one.
    if (const auto key = keys ? keys->next() : std::nullopt) {
      if (const auto mode = modeFromKey(*key)) session.select(*mode);
      if (*key == 'r') session.startRecording();
      if (*key == 's') session.stopRecording();
      if (*key == 'q' || *key == '0') session.quit();
    }
    if (slots.size() > 1) {
      const double d = control.divergence();
      worst_divergence = std::max(worst_divergence, d);
      if (reference.now() >= next_report) {
        spdlog::info("twin vs physical: largest joint divergence {:.4f} now, {:.4f} so far", d,
                     worst_divergence);
        next_report += 1.0;
      }
    }
    if (s.duration > 0.0 && reference.now() - start >= s.duration) break;
    const auto faulted = std::find_if(slots.begin(), slots.end(), [](auto& p) {
      return p.platform->operatingStatus().state == bridge::OperatingState::Fault;
    });
    if (faulted != slots.end()) {  // everything recorded so far is on disk
      spdlog::error("{} is in FAULT: stopping", faulted->name);
      break;
    }
  }
  const std::size_t rows = session.recording() ? session.stopRecording() : 0;
  spdlog::info("done: {} turns, {:.3f} s of platform time; {} recording file(s){}", turns,
               reference.now() - start, session.recordings().size(),
               rows ? " (" + std::to_string(rows) + " rows)" : std::string());
  for (const auto& file : session.recordings()) spdlog::info("  {}", file.string());
  if (slots.size() > 1) {
    spdlog::info("largest twin vs physical joint divergence: {:.4f}", worst_divergence);
  }
}

/// With a --start-from recording and --replay-ci inputs, the first move the recording's
/// controller made (controller::firstMoveOf); otherwise none.
std::optional<raven::ArmPair> firstMove(const recording::RsRecording* start_from,
                                        const std::vector<recording::GamepadState>& inputs,
                                        double deadzone) {
  if (!start_from || inputs.empty()) return std::nullopt;
  const recording::RsRecording& rs = *start_from;
  std::vector<raven::ArmPair> setpoints;
  for (std::size_t r = 0; r < rs.rows.size(); ++r) {
    setpoints.push_back({rs.signals(r, raven::Arm::Left).joint_setpoint,
                         rs.signals(r, raven::Arm::Right).joint_setpoint});
  }
  auto move = controller::firstMoveOf(setpoints, inputs, deadzone);
  if (!move) {
    spdlog::warn(
        "{}: its controller's first move does not show (the replay starts from the "
        "twin's own pose)",
        rs.path.string());
  } else {
    spdlog::info(
        "{}: the first iteration makes its controller's first move (roll {:+.4f} / "
        "{:+.4f} rad, left / right)",
        rs.path.string(), (*move)[0](raven::kRoll), (*move)[1](raven::kRoll));
  }
  return move;
}

int run(const Settings& s) {
  checkSettings(s);
  // Read once, and refused before anything moves.
  std::optional<controller_app::ControllerCalibration> calibration;
  if (!s.calibration_file.empty()) {
    calibration = controller_app::loadControllerCalibration(s.calibration_file);
  }
  controller::SessionInputs inputs;
  if (!s.replay_ci.empty()) inputs.inputs = recording::readCi(s.replay_ci);
  if (!s.replay_rs.empty()) {
    inputs.joints = recording::readRs(s.replay_rs);
    spdlog::info("{}: {}", s.replay_rs, inputs.joints->variant.describe());
  }
  std::optional<recording::RsRecording> start_from;
  if (!s.start_from.empty()) start_from = recording::readRs(s.start_from);
  const recording::RsRecording* start = start_from ? &*start_from : nullptr;
  std::optional<bridge::ros1::MasterWatch> master_watch;  // over ROS: survive a master restart
  if (s.platform != "twin" || s.twin_over_ros) {
    int argc = 1;
    char name[] = "raven_controller";
    char* argv[] = {name, nullptr};
    bridge::ros1::initRos(argc, argv, "raven_controller", /*ros_handles_sigint=*/false);
    master_watch.emplace();
  }
  Platforms platforms = makePlatforms(s, calibration ? &*calibration : nullptr, start);
  makeReady(platforms.slots);
  controller::DualPlatformController control(platforms.slots, controllerOptions(s, calibration));
  const auto first_move = firstMove(start, inputs.inputs, s.deadzone);

  std::unique_ptr<controller::SdlGamepad> pad;
  if (!s.no_gamepad && !s.lock_step) {
    pad = std::make_unique<controller::SdlGamepad>(s.trigger_range == "8bit"
                                                       ? controller::TriggerScale::EightBit
                                                       : controller::TriggerScale::XboxOne);
  }
  inputs.gamepad = pad.get();
  controller::SessionOptions session_options;
  session_options.out_dir = s.out_dir;
  session_options.record_name = s.name;
  session_options.end_after_replay = !s.replay_ci.empty() || !s.replay_rs.empty();
  controller::ControllerSession session(control, std::move(inputs), session_options);
  std::unique_ptr<controller::TerminalKeys> keys;
  if (!s.no_keyboard && !s.lock_step) {
    keys = std::make_unique<controller::TerminalKeys>(STDIN_FILENO);
    spdlog::info("keys: 1-5 modes O1-O5, r record, s stop recording, q quit");
  }
  if (const Mode first = firstMode(s, pad != nullptr); first != Mode::Idle) session.select(first);
  if (first_move) control.sendFirstMove(*first_move);  // once the replay has read the pose
  if (s.record == "yes") session.startRecording();
  turnUntilDone(session, control, platforms.slots, keys.get(), s);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "The Raven-II dual-platform controller: a gamepad (or a recording) drives the "
      "twin, the physical robot, or both with identical commands."};
  Settings s;
  app.add_option("--platform", s.platform, "twin (default, in-process), physical (ROS) or both")
      ->check(CLI::IsMember({"twin", "physical", "both"}));
  app.add_flag("--twin-over-ros", s.twin_over_ros,
               "reach the twin through a raven_twin_node instead of in-process");
  app.add_option("--twin-ns", s.twin_ns, "the twin node's ROS namespace (--twin-over-ros)");
  app.add_option("--physical-ns", s.physical_ns, "the physical robot's ROS namespace");
  app.add_flag("--no-arm-swap", s.no_arm_swap, "the robot publishes each arm on its own topic");
  common::addActuationFlag(app, s.actuation);
  app.add_option("--calibration", s.calibration_file,
                 "a profile fitted by raven_calibrate (YAML): the in-process twin's actuation "
                 "(default: twin/config/raven2_calibration.yaml), and replays timed as the "
                 "recording controller's iterations were")
      ->check(CLI::ExistingFile);
  app.add_option("--start-from", s.start_from,
                 "an rs recording: the in-process twin starts where it began (its joints, motors "
                 "and integrators), as a replay of that session should")
      ->check(CLI::ExistingFile);
  app.add_option("--twin-launch", s.twin_launch, "launch file of the twin's scene")
      ->check(CLI::ExistingFile);
  common::addVideoFlags(app, s.video, "the in-process twin");
  app.add_flag("--lock-step", s.lock_step,
               "simulated clock: replays run as fast as the CPU allows (twin only)");
  app.add_option("--mode", s.start_mode, "start in o1..o5")
      ->check(CLI::IsMember({"o1", "o2", "o3", "o4", "o5"}));
  app.add_option("--replay-ci", s.replay_ci, "O3: replay this controller-input file, then quit")
      ->check(CLI::ExistingFile);
  app.add_option("--replay-rs", s.replay_rs, "O4: replay this robot-state file's joints, then quit")
      ->check(CLI::ExistingFile);
  app.add_option("--record", s.record,
                 "write the rs and ci recordings from the start: yes or no (the r key records "
                 "either way); as raven_peg_transfer's --record")
      ->check(CLI::IsMember({"yes", "no"}));
  app.add_option("--name", s.name, "the recordings' file prefix (<name>_<time>_rs.csv, ...)");
  app.add_option("--out", s.out_dir, "where recordings go");
  app.add_option("--mapping", s.mapping, "initial mapping: m2, m1-left or m1-right")
      ->check(CLI::IsMember({"m2", "m1-left", "m1-right"}));
  app.add_option("--trigger-range", s.trigger_range,
                 "xbox-one (every pad's full travel) or 8bit (the released controller on an "
                 "8-bit trigger)")
      ->check(CLI::IsMember({"xbox-one", "8bit"}));
  app.add_flag("--paper-deadzone", s.paper_deadzone,
               "the released controller's deadzone test (reads the stick's Y twice), needed to "
               "replay the paper's recordings faithfully");
  app.add_flag("--no-gamepad", s.no_gamepad, "do not look for a gamepad");
  app.add_flag("--no-keyboard", s.no_keyboard, "do not read mode keys from the terminal");
  app.add_option("--duration", s.duration, "stop after this many seconds of platform time")
      ->check(common::kFiniteNonNegative);
  app.add_option("--rate", s.rate, "command steps per second (1..one per robot cycle)")
      ->check(common::finiteWithin(1.0, raven::kControlRate));
  app.add_option("--man-steps", s.man_steps,
                 "least steps per manual iteration; the pad is read between iterations, so this "
                 "bounds the input latency (10, the paper's, is needed to replay its recordings)")
      ->check(common::finiteWithin(1, 100));
  app.add_option("--deadzone", s.deadzone, "the sticks' radial deadzone (the paper's: 0.15)")
      ->check(common::finiteWithin(0.0, 0.9));
  app.add_option("--divisor", s.divisor,
                 "stick / divisor = metres per manual iteration (the paper's: 2000)")
      ->check(common::finiteWithin(200.0, 20000.0));
  app.add_option("--wrist-divisor", s.wrist_divisor,
                 "M1: stick / wrist-divisor = rad per iteration (the paper's: 10)")
      ->check(common::finiteWithin(2.0, 200.0));
  app.add_option("--velocity-scale", s.velocity_scale,
                 "C_V: the paper's joint speed caps times this (above 1: the twin only)")
      ->check(common::finiteWithin(0.05, 2.0));
  CLI11_PARSE(app, argc, argv);
  std::signal(SIGINT, [](int) { interrupted = true; });
  std::signal(SIGTERM, [](int) { interrupted = true; });
  try {
    return run(s);
  } catch (const std::exception& e) {
    spdlog::error("{}", e.what());
    return 1;
  }
}
