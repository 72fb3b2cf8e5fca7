// A policy's robustness (issue 68): the shipped RGB-D image policy evaluated on 20 draws of the
// randomisation at the edges of every range (scenario/ranges/edges.yaml), the same with the
// depth read as a stereo camera reads it (depth.yaml), on the shipped ranges and on the nominal
// scene, each as `python3 -m raven_sim.learn evaluate` in a child process; the points it loses
// at the edges against the nominal scene held to at most 10. About 45 minutes on two cores.

#include <fmt/format.h>
#include <stdlib.h>

#include "child_output.hpp"
#include "placed_rings.hpp"
#include "sections.hpp"

namespace bench {

namespace {

constexpr const char* kSection = "robustness";
constexpr double kLossBound = 10.0;  // points, issue 68's acceptance 2

/// One evaluation of the image policy: the scene options it runs with and what they mean.
struct SceneDraw {
  std::vector<std::string> options;  ///< e.g. {"--seeds", "1-20", "--nominal"}
  std::string what;                  ///< the row's name
};

std::optional<PlacedRings> evaluate(const SceneDraw& draw) {
  std::vector<std::string> argv{"/usr/bin/python3", "-m",       "raven_sim.learn",
                                "evaluate",         "--policy", RAVEN_IMAGE_POLICY,
                                "--workers",        "2"};
  argv.insert(argv.end(), draw.options.begin(), draw.options.end());
  const auto lines = outputLinesOf(argv, 3600.0);
  return lines ? placedRingsIn(*lines) : std::nullopt;
}

}  // namespace

void measurePolicyRobustness(const BenchSettings& s, Report& report) {
  setenv("PYTHONPATH", (s.programs / "python").c_str(), 1);
  const std::string how =
      "bc_rgbd.pt on the default twin (motor-level actuation), 240 s, two workers";
  // The nominal scene has no draw: its episodes differ only by the seed's noise, so two suffice.
  const SceneDraw nominal{{"--seeds", "1-2", "--nominal"}, "the nominal scene"};
  const SceneDraw shipped{{"--seeds", "1-20"}, "unseen seeds 1-20, the shipped ranges"};
  const SceneDraw edges{{"--seeds", "1-20", "--randomize", RAVEN_RANGES_DIR "/edges.yaml"},
                        "unseen seeds 1-20 at the ranges' edges (edges.yaml)"};
  const SceneDraw depth{{"--seeds", "1-20", "--randomize", RAVEN_RANGES_DIR "/depth.yaml"},
                        "the same with a stereo depth camera's errors (depth.yaml)"};
  std::vector<std::optional<PlacedRings>> results;
  for (const SceneDraw* draw : {&nominal, &shipped, &edges, &depth}) {
    results.push_back(evaluate(*draw));
    const std::string row = fmt::format("image policy: rings placed, {}", draw->what);
    if (!results.back()) {
      report.skip(kSection, row, "learn evaluate failed");
      continue;
    }
    report.add(measured(kSection, row, Spread::of({results.back()->percent()}), "%",
                        fmt::format("{}; {}", results.back()->summary(), how)));
  }
  const auto& [at_nominal, on_shipped, at_edges] = std::tie(results[0], results[1], results[2]);
  if (!at_nominal || !at_edges) return;
  report.add(atMost(kSection, "image policy: points lost at the edges against the nominal scene",
                    Spread::of({at_nominal->percent() - at_edges->percent()}), "points", kLossBound,
                    "negative: it places more at the edges"));
  if (on_shipped) {
    report.add(measured(
        kSection, "image policy: points lost at the edges against the shipped ranges",
        Spread::of({on_shipped->percent() - at_edges->percent()}), "points", "the same 20 seeds"));
  }
}

}  // namespace bench
