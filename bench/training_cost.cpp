// Learning at full size: scripts/retrain-policy.sh as a child process (the expert's
// demonstrations, behaviour cloning of the state policy, the policy on 20 unseen randomised
// scenes), its wall times and success taken into the report. One run: it takes about 25 minutes.

#include <fmt/format.h>

#include <regex>

#include "child_output.hpp"
#include "harness/temp_dir.hpp"
#include "sections.hpp"

namespace bench {

namespace {

constexpr const char* kSection = "training";

}  // namespace

void measureTraining(const BenchSettings& s, Report& report) {
  harness::TempDir work;  // the demonstrations and the policy
  const auto lines =
      outputLinesOf({RAVEN_RETRAIN_SCRIPT, s.programs.string(), work.path().string()}, 7200.0);
  if (!lines) {
    report.skip(kSection, "bc_state", "scripts/retrain-policy.sh failed");
    return;
  }
  const std::regex times(R"(recorded in (\d+) s, trained in (\d+) s)");
  const std::regex placed(R"(placed (\d+)/(\d+) rings; (\d+)/(\d+) episodes all six)");
  std::smatch m;
  for (const std::string& line : *lines) {
    if (std::regex_search(line, m, times)) {
      const std::string how = "scripts/retrain-policy.sh: two recordings side by side";
      report.add(measured(kSection, "expert demonstrations, 30 clean + 30 DART 0.3",
                          Spread::of({std::stod(m[1])}), "s", how));
      report.add(measured(kSection, "behaviour cloning, state policy (3 x 256, 30 epochs)",
                          Spread::of({std::stod(m[2])}), "s", "torch on the CPU, 2 threads"));
    } else if (std::regex_search(line, m, placed)) {
      const double share = 100.0 * std::stod(m[1]) / std::stod(m[2]);
      report.add(atLeast(kSection, "state policy: rings placed on unseen seeds 1-20",
                         Spread::of({share}), "%", 80.0,
                         fmt::format("{}/{} rings; {}/{} episodes all six", m[1].str(), m[2].str(),
                                     m[3].str(), m[4].str())));
    }
  }
}

}  // namespace bench
