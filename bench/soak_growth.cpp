// Long sessions: scripts/soak.sh's default ten-minute run (the twin node in lock-step at 1 kHz
// over ROS, then a peg-transfer batch), its RSS and step-time growth from the first tenth to the
// last.

#include <fmt/format.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "child_output.hpp"
#include "harness/temp_dir.hpp"
#include "sections.hpp"

namespace bench {

void measureSoak(const BenchSettings& s, Report& report) {
  const char* kSection = "soak";
  harness::TempDir dir;
  const auto figures = dir.path() / "soak.json";
  // The script fails at 5 % growth; its figures are written either way.
  outputLinesOf({"/usr/bin/env", "BUILD_DIR=" + s.programs.string(), RAVEN_SOAK_SCRIPT, "--json",
                 figures.string()},
                3600.0);
  std::ifstream in(figures);
  if (!in) {
    report.skip(kSection, "ten-minute soak", "scripts/soak.sh wrote no figures");
    return;
  }
  const auto soak = nlohmann::json::parse(in);
  const std::string what =
      fmt::format("scripts/soak.sh: session {}; batch {}", soak["session"].get<std::string>(),
                  soak["batch"].get<std::string>());
  report.add(atMost(kSection, "RSS growth, first to last tenth (worst process)",
                    Spread::of({soak["rss_growth_percent"].get<double>()}), "%", 5.0, what));
  report.add(atMost(kSection, "step time growth (CPU per simulated ms, worst of the two)",
                    Spread::of({soak["step_time_growth_percent"].get<double>()}), "%", 5.0,
                    soak["recording_whole"].get<bool>() ? "the session's recording whole"
                                                        : "the session's recording NOT whole"));
}

}  // namespace bench
