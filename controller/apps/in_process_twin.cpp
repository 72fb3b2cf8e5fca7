#include "in_process_twin.hpp"

#include <spdlog/spdlog.h>

#include "bridge/enable_and_home.hpp"
#include "raven/platform_profile.hpp"
#include "twin/calibration_profile.hpp"
#include "twin/recorded_start.hpp"
#include "twin/twin_platform.hpp"
#include "viewer/video_recorder.hpp"

namespace controller_app {

struct TwinActuation {
  twin::CalibrationProfile profile;
};

namespace {

/// The twin's video: opened at the first step (the world exists by then), closed with the twin.
struct TwinVideo {
  viewer::VideoOptions options;
  std::unique_ptr<viewer::VideoRecorder> recorder;

  void capture(const ambf_like::World& world) {
    if (!recorder) recorder = std::make_unique<viewer::VideoRecorder>(world, options, std::nullopt);
    recorder->capture(world);
  }
  ~TwinVideo() {
    if (!recorder) return;
    try {
      spdlog::info("video: {}", recorder->finish().describe());
    } catch (const std::exception& e) {
      spdlog::error("{}", e.what());
    }
  }
};

}  // namespace

std::unique_ptr<bridge::RavenPlatform> makeInProcessTwin(const InProcessTwinSettings& settings) {
  twin::TwinOptions options;
  if (!settings.launch_file.empty()) options.launch_file = settings.launch_file;
  options.clock = settings.lock_step ? bridge::ClockKind::Simulated : bridge::ClockKind::Wall;
  if (settings.actuation == common::ActuationKind::Motors) {
    (settings.calibration ? settings.calibration->twin_actuation->profile
                          : twin::CalibrationProfile::shipped())
        .applyTo(options);
  }
  if (!settings.video.file.empty()) {
    auto video = std::make_shared<TwinVideo>();
    video->options = viewer::VideoOptions::of(settings.video);
    video->options.visual_skin = raven::ravenVisualSkin();
    options.after_step = [video](const ambf_like::World& world) { video->capture(world); };
  }
  auto platform = std::make_unique<twin::TwinPlatform>(options);
  if (settings.start_from) {
    const auto start = twin::recordedStart(*settings.start_from);
    bridge::enableAndHome(*platform, 60.0);
    twin::startAt(*platform, start);
    spdlog::info("twin: placed where {} began", settings.start_from->path.string());
  }
  return platform;
}

ControllerCalibration loadControllerCalibration(const std::string& file) {
  auto profile = twin::CalibrationProfile::load(file);
  return {profile.iteration_overhead,
          std::make_shared<const TwinActuation>(TwinActuation{profile})};
}

}  // namespace controller_app
