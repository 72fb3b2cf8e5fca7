// What watching costs: the main job's loop frequency with the viewer window open (rendering at
// 30 fps on its own thread) against the same run headless.

#include <fmt/format.h>

#include <cstdlib>
#include <functional>
#include <memory>

#include "peg_scene.hpp"
#include "raven/platform_profile.hpp"
#include "sections.hpp"
#include "viewer/viewer.hpp"

namespace bench {

namespace {

const char* kSection = "viewer";

/// Opens a viewer window at the run's start and hands it every iteration; counts its frames.
struct Watcher {
  std::unique_ptr<viewer::Viewer> view;
  std::uint64_t frames = 0;
  void operator()(const ambf_like::World& world, scenario::WorldMoment moment, std::uint64_t) {
    if (moment == scenario::WorldMoment::Start) {
      viewer::ViewerOptions options;
      options.title = "raven_bench";
      view.reset();  // one viewer at a time
      view = std::make_unique<viewer::Viewer>(world, options);
    }
    view->publish(world);
    if (moment == scenario::WorldMoment::End) frames += view->framesDrawn();
  }
};

}  // namespace

void measureViewer(const BenchSettings& s, Report& report) {
  if (!std::getenv("DISPLAY")) {
    report.skip(kSection, "loop frequency with the window open",
                "no display (scripts/bench.sh runs the benchmark under xvfb-run)");
    return;
  }
  const auto launch = raven::modelDirectory() / "peg_transfer" / "launch.yaml";
  const double seconds = s.scene_seconds;
  const std::string how = fmt::format("main job's first {:.0f} s, {} runs", seconds, s.repeat);
  // Headless and windowed runs alternate, so a drift of the machine's speed hits both alike.
  Watcher watcher;
  const scenario::WorldObserver observe = std::ref(watcher);
  std::vector<double> headless, windowed, ratios;
  for (int i = 0; i < s.repeat; ++i) {
    headless.push_back(pegScene({.launch = launch, .seconds = seconds}, 1).front().whole);
    windowed.push_back(
        pegScene({.launch = launch, .seconds = seconds, .observe = observe}, 1).front().whole);
    ratios.push_back(windowed.back() / headless.back());
  }
  report.add(measured(kSection, "peg-transfer scene, free-running, headless", Spread::of(headless),
                      "steps/s", how));
  report.add(measured(kSection, "peg-transfer scene, free-running, viewer window open",
                      Spread::of(windowed), "steps/s",
                      how + fmt::format(", {} frames drawn", watcher.frames)));
  report.add(atLeast(kSection, "window open / headless", Spread::of(ratios), "x", 0.9,
                     "run by run, alternating; the window renders at 30 fps on its own thread"));
  report.add(atLeast(
      kSection, "peg-transfer scene, paced at 1 kHz, viewer window open",
      Spread::of(wholeRates(pegScene(
          {.launch = launch, .clock = bridge::ClockKind::Wall, .seconds = 10.0, .observe = observe},
          1))),
      "steps/s", 900, "first 10 s on the wall clock; within 10 % of the 1 kHz it holds headless"));
}

}  // namespace bench
