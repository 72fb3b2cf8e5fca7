// What a video costs: the main job's real-time factor while it records a video (drawn headless
// and encoded on the recorder's own thread) against the same job without one, alternating.

#include <fmt/format.h>

#include <functional>

#include "harness/temp_dir.hpp"
#include "peg_scene.hpp"
#include "raven/platform_profile.hpp"
#include "scenario/run_watcher.hpp"
#include "sections.hpp"

namespace bench {

namespace {

const char* kSection = "video";
constexpr double kWholeJob = 240.0;  ///< the main job's time limit: every run goes to its end

}  // namespace

void measureVideo(const BenchSettings& s, Report& report) {
  const auto launch = raven::modelDirectory() / "peg_transfer" / "launch.yaml";
  harness::TempDir dir;
  const std::vector<std::string> sizes{"960x540", "640x360"};
  std::vector<std::vector<double>> with_video(sizes.size());
  std::vector<double> without;
  std::int64_t frames = 0;
  try {
    for (int i = 0; i < s.repeat; ++i) {
      without.push_back(pegScene({.launch = launch, .seconds = kWholeJob}, 1).front().whole);
      for (std::size_t k = 0; k < sizes.size(); ++k) {
        scenario::WatchOptions watch;
        watch.video = dir.path() / fmt::format("run_{}_{}.mp4", k, i);
        watch.video_options.setSize(sizes[k]);
        scenario::RunWatcher watcher(watch);
        with_video[k].push_back(
            pegScene({.launch = launch, .seconds = kWholeJob, .observe = std::ref(watcher)}, 1)
                .front()
                .whole);
        frames = watcher.videos().front().frames;
      }
    }
  } catch (const viewer::NoDisplay& e) {
    report.skip(kSection, "real-time factor with a video", e.what());
    return;
  }
  auto rtf = [](std::vector<double> steps_per_s) {  // 1 ms steps: steps/s / 1000
    for (double& v : steps_per_s) v /= 1000.0;
    return Spread::of(steps_per_s);
  };
  const std::string how = fmt::format("whole main job, {} runs, alternating", s.repeat);
  report.add(measured(kSection, "main job, no video", rtf(without), "x real time", how));
  for (std::size_t k = 0; k < sizes.size(); ++k) {
    std::vector<double> ratio;
    for (int i = 0; i < s.repeat; ++i) ratio.push_back(with_video[k][i] / without[i]);
    report.add(measured(kSection, fmt::format("main job, video {} at 30 fps", sizes[k]),
                        rtf(with_video[k]), "x real time",
                        fmt::format("{}; {} frames of H.264 per run", how, frames)));
    report.add(measured(kSection, fmt::format("video {} / no video", sizes[k]), Spread::of(ratio),
                        "x", "run by run"));
  }
}

}  // namespace bench
