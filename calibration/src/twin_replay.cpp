#include "calibration/twin_replay.hpp"

#include "bridge/enable_and_home.hpp"
#include "controller/session.hpp"
#include "recording/recording_format.hpp"

namespace calibration {

analysis::Trial replayOnTwin(const ReplaySetup& setup) {
  analysis::RecordingSource twin_profile;  // the twin records in the robot's convention
  twin_profile.name = "twin";
  return analysis::toTrial(recordReplay(setup), twin_profile);
}

recording::RsRecording recordReplay(const ReplaySetup& setup) {
  twin::TwinOptions twin_options = setup.twin;
  twin_options.clock = bridge::ClockKind::Simulated;
  twin::TwinPlatform twin(twin_options);
  bridge::enableAndHome(twin, 30.0);
  if (setup.start) twin::startAt(twin, *setup.start);
  controller::DualPlatformController control({{"twin", &twin, controller::CommandStyle::ServoJr}},
                                             setup.controller);

  recording::RsRecording rs;
  rs.path = "twin replay";
  rs.names = recording::rsColumnNames();
  double t0 = 0.0;
  controller::SessionOptions options;
  options.replay_delay = setup.replay_delay;
  options.end_after_replay = true;
  options.on_state = [&](std::size_t, const bridge::RavenStateSnapshot& state) {
    if (rs.rows.empty()) t0 = state.time;
    rs.rows.push_back(recording::rsRow(state, t0));
  };
  controller::SessionInputs inputs;
  inputs.inputs = setup.inputs;
  controller::ControllerSession session(control, std::move(inputs), options);
  session.select(controller::Mode::ReplayInputs);  // reads the pose
  if (setup.first_move) control.sendFirstMove(*setup.first_move);
  while (session.turn()) {
  }
  return rs;
}

}  // namespace calibration
