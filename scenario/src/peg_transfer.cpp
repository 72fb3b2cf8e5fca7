#include "scenario/peg_transfer.hpp"

#include <algorithm>
#include <memory>
#include <optional>

#include "ambf_like/scene_loader.hpp"
#include "recording/cf_recording.hpp"
#include "recording/recording_io.hpp"
#include "scenario/arm_routine.hpp"
#include "scenario/carried_squeeze.hpp"
#include "scenario/grasp_assist.hpp"
#include "scenario/peg_watch.hpp"
#include "scenario/scripted_session.hpp"
#include "twin/calibration_profile.hpp"

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
  if (options.motor_actuation) twin::CalibrationProfile::shipped().applyTo(twin);
  return twin;
}

std::array<ArmRoutine, 2> pegTransferOperators(const PegLayout& layout, double squeeze) {
  const auto profile = raven::builtinProfile("physical");
  return {
      ArmRoutine(raven::Arm::Left, profile, layout, layout.jobsOf(raven::Arm::Left), squeeze),
      ArmRoutine(raven::Arm::Right, profile, layout, layout.jobsOf(raven::Arm::Right), squeeze)};
}

PegTransferResult runPegTransfer(const PegTransferOptions& options) {
  PegTransferResult result;
  result.variation = options.randomize ? SceneVariation::draw(options.seed) : SceneVariation{};
  result.variation.seed = options.seed;
  result.assist = options.assist;
  result.motor_actuation = options.motor_actuation;

  ScriptedSession session(pegTransferTwin(options, result.variation));
  ambf_like::World& world = session.twin().world();
  const PegLayout layout;
  PegWatch watch(world, layout);  // rest volumes: before the first step
  CarriedSqueeze squeeze;
  session.makeReady(options.time_limit);
  controller::DualPlatformController& controller = session.controller();
  twin::TwinPlatform& twin = session.twin();

  std::array<ArmRoutine, 2> routines = pegTransferOperators(layout, options.squeeze);
  std::optional<GraspAssist> assist;
  if (options.assist == AssistMode::Contact) {
    std::vector<std::string> pegs;
    for (const PegJob& job : layout.jobs) pegs.push_back(job.peg);
    assist.emplace(world, pegs);
  }
  std::unique_ptr<recording::RsWriter> rs;
  std::unique_ptr<recording::CfWriter> cf;
  const std::filesystem::path rs_file =
      !options.rs_file.empty() || options.rs_folder.empty()
          ? options.rs_file
          : options.rs_folder / ("peg_transfer_seed" + std::to_string(options.seed) + "_rs.csv");
  if (!rs_file.empty()) {
    rs = std::make_unique<recording::RsWriter>(rs_file);
    cf = std::make_unique<recording::CfWriter>(recording::cfPathFor(rs_file));
  }

  RunProgress progress{twin.now(), 0, layout.jobs.size()};
  auto show = [&](WorldMoment moment) {
    if (options.observe) options.observe(world, moment, options.seed);
  };
  show(WorldMoment::Start);
  auto done = [&] { return routines[0].done() && routines[1].done(); };
  try {
    while (!done() && twin.now() < options.time_limit && !options.stopRequested()) {
      const controller::ArmPair current = controller.commanded();
      const controller::ArmPair next{routines[0].next(current[0], world),
                                     routines[1].next(current[1], world)};
      result.refused += controller.moveTo(next).refused;
      if (assist) {
        for (raven::Arm arm : raven::kArms)
          assist->update(arm, routines[raven::index(arm)].opening());
      }
      if (rs) {
        const auto state = *twin.ravenState();
        rs->write(state);
        cf->write(state.time,
                  {twin.measuredCf(raven::Arm::Left), twin.measuredCf(raven::Arm::Right)});
      }
      for (const ArmRoutine& routine : routines) {
        const auto forces = twin.measuredCf(routine.arm());
        if (routine.phase() == Phase::Carry && forces && routine.carrying(world)) {
          squeeze.record(routine.jobs()[routine.finished()].peg, *forces);
        }
      }
      watch.observe();
      ++result.iterations;
      progress.sim_time = twin.now();
      progress.done = routines[0].finished() + routines[1].finished();
      progress.carrying = static_cast<std::size_t>(
          std::count_if(routines.begin(), routines.end(), [](const ArmRoutine& r) {
            return r.phase() == Phase::Lift || r.phase() == Phase::Carry ||
                   r.phase() == Phase::Lower;
          }));
      if (options.progress) options.progress(progress);
      show(WorldMoment::Iteration);
    }
    result.stopped = !done() && options.stopRequested();
    result.timed_out = !done() && !result.stopped;
    const double settle_end = twin.now() + (result.stopped ? 0.0 : options.settle_time);
    while (twin.now() < settle_end) {
      controller.idle();
      watch.observe();
      show(WorldMoment::Iteration);
    }
  } catch (const ambf_like::SimulationDiverged& e) {
    // The run stops here; its rings' numbers are not results (PegTransferResult::failure).
    result.failure = e.what();
  }
  show(WorldMoment::End);

  result.timing = session.timing();
  if (rs) {
    result.rs_file = rs->path();
    result.rs_rows = rs->rows();
  }
  if (!result.failure.empty()) return result;
  result.pegs = watch.finish();
  for (PegOutcome& outcome : result.pegs) outcome.carried_squeeze = squeeze.median(outcome.peg);
  for (const ArmRoutine& routine : routines) {
    for (std::size_t j = 0; j < routine.jobs().size(); ++j) {
      for (PegOutcome& outcome : result.pegs) {
        if (outcome.peg == routine.jobs()[j].peg) outcome.regrasps = routine.regrasps()[j];
      }
    }
  }
  result.grasps = assist ? assist->grasps() : 0;
  return result;
}

}  // namespace scenario
