#include "study/trial_runner.hpp"

#include <spdlog/spdlog.h>

#include <chrono>

#include "ambf_like/step_guard.hpp"
#include "controller/session.hpp"
#include "raven/arm_kinematics.hpp"
#include "raven/platform_profile.hpp"
#include "scenario/scripted_session.hpp"
#include "study/collision_watch.hpp"
#include "study/view_watch.hpp"
#include "twin/calibration_profile.hpp"

namespace study {

namespace {

/// How long a homing may take (s of platform time).
constexpr double kHomingLimit = 60.0;

/// The body whose origin is each arm's jaw axis.
std::string jawBody(raven::Arm arm) {
  return "/raven2/" + std::string(raven::armName(arm)) + "/jaw1_link";
}

/// When the settings ask for a video: the trial filmed from the task camera into `video`, from
/// the first step after `camera` is set (homing is not filmed).
void filmTrial(const TrialSettings& s, const std::optional<viewer::View>& camera,
               std::unique_ptr<viewer::VideoRecorder>& video, twin::TwinOptions& options) {
  if (!s.video) return;
  options.after_step = [&s, &camera, &video](const ambf_like::World& world) {
    if (!camera) return;
    if (!video) {
      viewer::VideoOptions film = *s.video;
      film.file = s.dir / "trial.mp4";
      film.visual_skin = raven::ravenVisualSkin();
      video = std::make_unique<viewer::VideoRecorder>(world, film, camera);
    }
    video->capture(world);
  };
}

/// Brings the arms under the caps to the tools the task starts them at (the within-limits joints
/// nearest the homed ones; a grasper turned half a turn about its jaws is the same grasper), and
/// lets them settle for half a second.
void placeArms(const TrialTask& task, const raven::PlatformProfile& profile,
               twin::TwinPlatform& twin, controller::DualPlatformController& control) {
  const auto tools = task.startTools();
  if (!tools) return;
  controller::ArmPair joints;
  for (raven::Arm arm : raven::kArms) {
    const auto a = raven::slot(arm);
    const auto kinematics = raven::ArmKinematics::of(profile, arm);
    const raven::ArmJoints homed = twin.measuredJs(arm).position;
    std::optional<raven::ArmJoints> best;
    for (const double turn : {0.0, M_PI}) {
      Eigen::Isometry3d tool = (*tools)[a];
      tool.linear() = tool.linear() * Eigen::AngleAxisd(turn, Eigen::Vector3d::UnitX());
      const auto q = kinematics.inverseWithinLimits(tool, 1.0, homed);
      if (q && (!best || raven::ArmKinematics::distance(*q, homed) <
                             raven::ArmKinematics::distance(*best, homed))) {
        best = q;
      }
    }
    if (!best)
      throw std::runtime_error("the task's start pose of the " + std::string(raven::armName(arm)) +
                               " arm is out of reach");
    joints[a] = *best;
  }
  control.moveTo(joints);
  for (double t = 0.0; t < 0.5; t += control.period()) control.idle();
}

/// What the task sees of the twin: the tools from the encoders, the jaws from the world.
class TwinSight {
 public:
  TwinSight(const twin::TwinPlatform& twin, const raven::PlatformProfile& profile)
      : twin_(twin),
        kinematics_{raven::ArmKinematics::of(profile, raven::Arm::Left),
                    raven::ArmKinematics::of(profile, raven::Arm::Right)},
        jaws_{&twin.world().body(jawBody(raven::Arm::Left)),
              &twin.world().body(jawBody(raven::Arm::Right))} {}

  /// The view at `time` s of trial time.
  TaskView operator()(double time) const {
    TaskView v;
    v.time = time;
    for (raven::Arm arm : raven::kArms) {
      const auto a = raven::slot(arm);
      const Eigen::Isometry3d tool = kinematics_[a].toolPose(twin_.measuredJs(arm).position);
      v.tips[a] = tool.translation();
      v.tool_axes[a] = tool.linear();
      v.jaws[a] = jaws_[a]->pose().translation();
    }
    v.world = &twin_.world();
    return v;
  }

 private:
  const twin::TwinPlatform& twin_;
  raven::PerArm<raven::ArmKinematics> kinematics_;
  raven::PerArm<const ambf_like::RigidBody*> jaws_;
};

}  // namespace

recording::GamepadState gatePad(const Condition& condition, recording::GamepadState pad,
                                bool first) {
  if (condition.scheme != "m1" || (pad.back && pad.start)) pad.back = pad.start = false;
  pad.a = first && !condition.full_ik;
  pad.b = first && condition.full_ik;
  return pad;
}

raven::PerArm<bool> armsMoved(const Condition& condition) {
  if (condition.scheme == "m1-left") return {true, false};
  if (condition.scheme == "m1-right") return {false, true};
  return {true, true};
}

TrialRun runTrial(const TrialSettings& s) {
  std::filesystem::create_directories(s.dir);
  const auto task = makeTask(s.task, s.task_seed, armsMoved(s.condition));

  twin::TwinOptions twin_options;
  if (const auto launch = task->launchFile(); !launch.empty()) twin_options.launch_file = launch;
  twin_options.clock = s.wall_clock ? bridge::ClockKind::Wall : bridge::ClockKind::Simulated;
  twin::CalibrationProfile::shipped().applyTo(twin_options);  // the robot's own motors
  std::unique_ptr<viewer::VideoRecorder> video;  // opened at the first step of the trial
  std::optional<viewer::View> camera;            // the task's, once the twin is homed
  filmTrial(s, camera, video, twin_options);
  scenario::ScriptedSession scripted(twin_options, s.condition.controllerOptions());
  scripted.makeReady(kHomingLimit);
  twin::TwinPlatform& twin = scripted.twin();
  controller::DualPlatformController& control = scripted.controller();
  const auto profile = raven::builtinProfile(s.condition.controllerOptions().profile);
  double start = twin.now();  // the trial's clock starts once the arms are placed
  const auto view = [&, see = TwinSight(twin, profile)] { return see(twin.now() - start); };

  EventLog events(s.dir / "events.csv");
  bool first = true, clamped = false, capped = false;
  controller::SessionOptions options;
  options.out_dir = s.dir;
  options.record_name = "trial";
  options.gate = [&](const recording::GamepadState& pad) {
    const auto gated = gatePad(s.condition, pad, first);
    first = false;
    return gated;
  };
  options.on_iteration = [&](const controller::IterationReport& r) {
    const double t = twin.now() - start;
    if (r.clamped && !clamped) events.add(t, "joint_limit");
    if (r.capped && !capped) events.add(t, "velocity_cap");
    clamped = r.clamped;
    capped = r.capped;
  };
  controller::ControllerSession session(control, {s.pad, {}, std::nullopt}, options);

  TrialRun run;
  if (s.ready && !s.ready()) return run;
  placeArms(*task, profile, twin, control);
  start = twin.now();
  const TaskView first_view = view();
  camera = task->camera(first_view);
  CollisionWatch collisions(task->board());
  const viewer::VideoOptions picture = s.video.value_or(viewer::VideoOptions{});
  ViewWatch sight(camera->camera, picture.width, picture.height);
  task->begin(first_view, events);
  events.add(0.0, "trial_start", -1, s.task.time_limit);
  events.add(0.0, "force_threshold", -1, s.task.excessive_force);
  session.select(controller::Mode::Manual);
  session.startRecording();
  double next_status = 0.0;
  for (TaskView now = view();;) {
    run.completed = task->done();
    if (run.completed || now.time >= s.task.time_limit) break;
    if (s.stop && *s.stop) {
      events.add(now.time, "stopped");
      return run;
    }
    if (s.before_turn) s.before_turn(now.time, task->goals(), now.tips);
    try {
      session.turn();
    } catch (const ambf_like::SimulationDiverged& e) {  // the world cannot go on, nor the trial
      spdlog::error("{}", e.what());
      events.add(now.time, "simulation_diverged");
      run.diverged = true;
      break;
    }
    now = view();
    run.e_stopped = twin.operatingStatus().state == bridge::OperatingState::Fault;
    if (run.e_stopped) {  // an e-stop ends the trial: the robot needs the experimenter
      events.add(now.time, "robot_fault");
      break;
    }
    task->observe(now, events);
    collisions.observe(now.time, now.world->contacts(), events);
    sight.observe(now.time, now.jaws, events);
    if (s.status && now.time >= next_status) {
      s.status(task->status(now) +
               (collisions.touchingBoard() ? "  (a tool touches the board)" : ""));
      next_status = now.time + 0.1;
    }
  }
  session.stopRecording();
  if (video) spdlog::info("video: {}", video->finish().describe());
  run.duration = twin.now() - start;
  run.finished = true;
  events.add(run.duration, "trial_end", -1, run.completed ? 1.0 : 0.0);
  return run;
}

}  // namespace study
