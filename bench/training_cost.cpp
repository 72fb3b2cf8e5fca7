// Learning at full size: scripts/retrain-policy.sh as a child process (the expert's
// demonstrations, behaviour cloning of the state policy, the policy on 20 unseen randomised
// scenes), its wall times and success taken into the report. One run: it takes about 20 minutes.

#include <fmt/format.h>

#include <fstream>
#include <regex>

#include "harness/child_process.hpp"
#include "harness/temp_dir.hpp"
#include "sections.hpp"

namespace bench {

namespace {

constexpr const char* kSection = "training";

}  // namespace

void measureTraining(const BenchSettings& s, Report& report) {
  harness::TempDir dir;
  const auto log = dir.path() / "retrain.log";
  harness::ChildProcess run({RAVEN_RETRAIN_SCRIPT, s.programs.string(), dir.path().string()}, log);
  if (run.wait(7200.0) != 0) {
    report.skip(kSection, "bc_state", "scripts/retrain-policy.sh failed");
    return;
  }
  std::ifstream in(log);
  const std::regex times(R"(recorded in (\d+) s, trained in (\d+) s)");
  const std::regex placed(R"(placed (\d+)/(\d+) rings; (\d+)/(\d+) episodes all six)");
  std::string line;
  std::smatch m;
  while (std::getline(in, line)) {
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
