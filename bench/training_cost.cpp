// Learning at full size: scripts/retrain-policy.sh and scripts/retrain-image-policy.sh as child
// processes (the expert's demonstrations, behaviour cloning, the policy on 20 unseen randomised
// scenes), their wall times and success taken into the report. One run of each: about 25 and 45
// minutes.

#include <fmt/format.h>

#include <regex>

#include "child_output.hpp"
#include "harness/temp_dir.hpp"
#include "placed_rings.hpp"
#include "sections.hpp"

namespace bench {

namespace {

constexpr const char* kSection = "training";

/// One retraining script and how its rows are named.
struct Retraining {
  const char* script;
  const char* policy;     ///< "state policy", "image policy"
  const char* demos;      ///< what its recordings are
  const char* training;   ///< what its training is
  double target_percent;  ///< the rings it must place on unseen seeds (0: a report only)
};

void measure(const BenchSettings& s, Report& report, const Retraining& r) {
  harness::TempDir work;  // the demonstrations and the policy
  const auto lines = outputLinesOf({r.script, s.programs.string(), work.path().string()}, 7200.0);
  if (!lines) {
    report.skip(kSection, r.policy, fmt::format("{} failed", r.script));
    return;
  }
  const std::regex times(R"(recorded in (\d+) s, trained in (\d+) s)");
  std::smatch m;
  for (const std::string& line : *lines) {
    if (!std::regex_search(line, m, times)) continue;
    report.add(measured(kSection, fmt::format("{}: expert demonstrations, {}", r.policy, r.demos),
                        Spread::of({std::stod(m[1])}), "s", "two recordings side by side"));
    report.add(measured(kSection, fmt::format("{}: {}", r.policy, r.training),
                        Spread::of({std::stod(m[2])}), "s", "torch on the CPU, 2 threads"));
  }
  if (const auto placed = placedRingsIn(*lines)) {
    const std::string row = fmt::format("{}: rings placed on unseen seeds 1-20", r.policy);
    const Spread share = Spread::of({placed->percent()});
    report.add(r.target_percent > 0.0
                   ? atLeast(kSection, row, share, "%", r.target_percent, placed->summary())
                   : measured(kSection, row, share, "%", placed->summary()));
  }
}

}  // namespace

void measureTraining(const BenchSettings& s, Report& report) {
  measure(s, report,
          {RAVEN_RETRAIN_SCRIPT, "state policy", "30 clean + 30 DART 0.3",
           "behaviour cloning (3 x 256, 30 epochs)", 80.0});
  // The issue asks the image policy to aim for half the rings: a report, not a floor.
  measure(s, report,
          {RAVEN_RETRAIN_IMAGE_SCRIPT, "image policy", "40 clean + 20 DART 0.3, two cameras",
           "ring locator from 128 x 96 images (16 epochs)", 0.0});
}

}  // namespace bench
