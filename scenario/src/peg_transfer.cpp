#include "scenario/peg_transfer.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <memory>
#include <optional>

#include "ambf_like/scene_loader.hpp"
#include "bridge/enable_and_home.hpp"
#include "raven/control_cycle.hpp"
#include "recording/cf_recording.hpp"
#include "recording/recording_io.hpp"
#include "scenario/arm_routine.hpp"
#include "scenario/carried_squeeze.hpp"
#include "scenario/grasp_assist.hpp"
#include "scenario/ring_watch.hpp"
#include "scenario/scripted_session.hpp"
#include "twin/calibration_profile.hpp"
#include "twin/world_perception.hpp"

namespace scenario {

twin::TwinOptions pegTransferTwin(const PegTransferOptions& options,
                                  const SceneVariation& variation) {
  twin::TwinOptions twin;
  twin.launch_file = options.launch_file.empty()
                         ? raven::modelDirectory() / "peg_transfer" / "launch.yaml"
                         : options.launch_file;
  twin.clock = options.clock;
  const bool assist = options.assist == AssistMode::Contact;
  twin.adjust_scene = [variation, sleep = options.soft_body_sleep,
                       assist](ambf_like::SceneSpec& scene) {
    variation.apply(scene);
    scene.world.soft_body_sleep.enabled = sleep;
    // The assist's jaw sensors and actuators, after the arms whose jaws carry them.
    if (assist) ambf_like::appendModelFiles(scene, {GraspAssist::modelFile()});
  };
  if (options.actuation == common::ActuationKind::Motors) {
    const twin::CalibrationProfile calibration =
        options.calibration.empty() ? twin::CalibrationProfile::shipped()
                                    : twin::CalibrationProfile::load(options.calibration);
    calibration.applyTo(twin);
    twin.motors = variation.mechanics(calibration.mechanics, calibration.uncertainty);
  }
  return twin;
}

raven::PerArm<ArmRoutine> pegTransferOperators(const PegLayout& layout, double squeeze) {
  const auto profile = raven::builtinProfile("physical");
  return {
      ArmRoutine(raven::Arm::Left, profile, layout, layout.jobsOf(raven::Arm::Left), squeeze),
      ArmRoutine(raven::Arm::Right, profile, layout, layout.jobsOf(raven::Arm::Right), squeeze)};
}

namespace {

/// What an in-process run adds to the job, both on the world: the grasp assist (after every
/// move) and the viewer.
struct InProcessHooks {
  std::function<void(const raven::PerArm<ArmRoutine>&)> after_move = [](const auto&) {};
  std::function<void(WorldMoment)> show = [](WorldMoment) {};
};

/// The platform went to FAULT: it takes no more commands.
class PlatformFault : public std::runtime_error {
 public:
  PlatformFault() : std::runtime_error("the platform reported FAULT") {}
};

/// The rs file a run writes, or none.
std::filesystem::path rsFileOf(const PegTransferOptions& options) {
  if (!options.rs_file.empty() || options.rs_folder.empty()) return options.rs_file;
  return options.rs_folder / ("peg_transfer_seed" + std::to_string(options.seed) + "_rs.csv");
}

/// The job on a ready platform: the scripted operators move, the watch judges, both through
/// `scene`; fills the result's rings, counts and recording.
void runJob(bridge::RavenPlatform& platform, controller::DualPlatformController& controller,
            bridge::ScenePerception& scene, const PegTransferOptions& options,
            const InProcessHooks& hooks, PegTransferResult& result) {
  scene.update(platform.now());
  const PegLayout layout = PegLayout::seen(scene);
  RingWatch watch(layout);
  CarriedSqueeze squeeze;
  raven::PerArm<ArmRoutine> routines = pegTransferOperators(layout, options.squeeze);
  std::unique_ptr<recording::RsWriter> rs;
  std::unique_ptr<recording::CfWriter> cf;
  if (const auto rs_file = rsFileOf(options); !rs_file.empty()) {
    rs = std::make_unique<recording::RsWriter>(rs_file);
    cf = std::make_unique<recording::CfWriter>(recording::cfPathFor(rs_file));
  }
  RunProgress progress{platform.now(), 0, layout.jobs.size()};
  hooks.show(WorldMoment::Start);
  auto done = [&] { return routines[0].done() && routines[1].done(); };
  auto faulted = [&] { return platform.operatingStatus().state == bridge::OperatingState::Fault; };
  try {
    while (!done() && platform.now() < options.time_limit && !options.stopRequested()) {
      const controller::ArmPair current = controller.commanded();
      const controller::ArmPair next{
          routines[0].next(current[0], platform.measuredJs(raven::Arm::Left).position, scene),
          routines[1].next(current[1], platform.measuredJs(raven::Arm::Right).position, scene)};
      result.refused += controller.moveTo(next).refused;
      if (faulted()) throw PlatformFault();
      scene.update(platform.now());
      hooks.after_move(routines);
      if (rs) {
        if (const auto state = platform.ravenState()) {
          rs->write(*state);
          cf->write(state->time, {platform.measuredCf(raven::Arm::Left),
                                  platform.measuredCf(raven::Arm::Right)});
        }
      }
      for (const ArmRoutine& routine : routines) {
        const auto forces = platform.measuredCf(routine.arm());
        if (routine.phase() == Phase::Carry && forces && routine.carrying(scene)) {
          squeeze.record(routine.jobs()[routine.finished()].ring, *forces);
        }
      }
      watch.observe(scene);
      ++result.iterations;
      progress.sim_time = platform.now();
      progress.done = routines[0].finished() + routines[1].finished();
      progress.carrying = static_cast<std::size_t>(
          std::count_if(routines.begin(), routines.end(), [](const ArmRoutine& r) {
            return r.phase() == Phase::Lift || r.phase() == Phase::Carry ||
                   r.phase() == Phase::Lower;
          }));
      if (options.progress) options.progress(progress);
      hooks.show(WorldMoment::Iteration);
    }
    result.stopped = !done() && options.stopRequested();
    result.timed_out = !done() && !result.stopped;
    const double settle_end = platform.now() + (result.stopped ? 0.0 : options.settle_time);
    while (platform.now() < settle_end) {
      controller.idle();
      if (faulted()) throw PlatformFault();
      scene.update(platform.now());
      watch.observe(scene);
      hooks.show(WorldMoment::Iteration);
    }
  } catch (const ambf_like::SimulationDiverged& e) {
    // A world that blew up, a platform in FAULT or rings no longer seen: the run stops here
    // and its rings' numbers are not results (PegTransferResult::failure).
    result.failure = e.what();
  } catch (const PlatformFault& e) {
    result.failure = e.what();
  } catch (const bridge::PerceptionError& e) {
    result.failure = e.what();
  }
  hooks.show(WorldMoment::End);
  if (rs) {
    result.rs_file = rs->path();
    result.rs_rows = rs->rows();
  }
  if (!result.failure.empty()) return;
  result.rings = watch.finish(scene);
  for (RingOutcome& outcome : result.rings) outcome.carried_squeeze = squeeze.median(outcome.ring);
  for (const ArmRoutine& routine : routines) {
    for (std::size_t j = 0; j < routine.jobs().size(); ++j) {
      for (RingOutcome& outcome : result.rings) {
        if (outcome.ring == routine.jobs()[j].ring) outcome.regrasps = routine.regrasps()[j];
      }
    }
  }
}

}  // namespace

PegTransferResult runPegTransfer(const PegTransferOptions& options) {
  PegTransferResult result;
  result.variation =
      options.randomize ? SceneVariation::draw(options.seed, options.ranges) : SceneVariation{};
  result.variation.seed = options.seed;
  result.assist = options.assist;
  result.actuation = options.actuation;

  ScriptedSession session(pegTransferTwin(options, result.variation));
  twin::TwinPlatform& twin = session.twin();
  const ambf_like::World& world = twin.world();
  twin::WorldPerception scene(world);
  session.makeReady(options.time_limit);

  InProcessHooks hooks;
  std::optional<GraspAssist> assist;
  if (options.assist == AssistMode::Contact) {
    std::vector<std::string> rings;
    for (const RingJob& job : PegLayout::seen(scene).jobs) rings.push_back(job.ring);
    assist.emplace(twin.world(), rings);
    hooks.after_move = [&](const raven::PerArm<ArmRoutine>& routines) {
      for (const ArmRoutine& routine : routines) assist->update(routine.arm(), routine.opening());
    };
  }
  if (options.observe) {
    hooks.show = [&](WorldMoment moment) { options.observe(world, moment, options.seed); };
  }
  runJob(twin, session.controller(), scene, options, hooks, result);
  result.timing = session.timing();
  result.grasps = assist ? assist->grasps() : 0;
  return result;
}

PegTransferResult runPegTransferOn(bridge::RavenPlatform& platform, bridge::ScenePerception& scene,
                                   const PegTransferOptions& options) {
  using Clock = std::chrono::steady_clock;
  const auto wall_start = Clock::now();
  PegTransferResult result;
  result.variation.seed = options.seed;
  const double sim_start = platform.now();
  bridge::enableAndHome(platform, options.time_limit - platform.now());
  controller::DualPlatformController controller(
      {{"robot", &platform, controller::CommandStyle::ServoJr}}, {});
  controller.readPose();
  const auto loop_start = Clock::now();
  runJob(platform, controller, scene, options, {}, result);
  const auto end = Clock::now();
  result.timing.sim_time = platform.now();
  result.timing.wall_time = std::chrono::duration<double>(end - wall_start).count();
  result.timing.loop_seconds = std::chrono::duration<double>(end - loop_start).count();
  result.timing.steps =
      static_cast<std::uint64_t>(std::llround((platform.now() - sim_start) / raven::kControlCycle));
  return result;
}

}  // namespace scenario
