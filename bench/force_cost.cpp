// The forces behind a recording's motor signals: rows per second of raven_analyze forces'
// estimate (both arms, the shipped calibration) on the robot's 2arm trial.

#include <fmt/format.h>

#include <chrono>

#include "analysis/force_report.hpp"
#include "sections.hpp"

namespace bench {

void measureForces(const BenchSettings& s, Report& report) {
  const auto trial = s.shared_data / "recordings/paper_2arm/2arm_physical_1.csv";
  if (!std::filesystem::exists(trial)) {
    report.skip("forces", "force estimate from a recording", "../shared/data is absent");
    return;
  }
  const auto profile = twin::CalibrationProfile::shipped();
  std::vector<double> rates;
  std::size_t rows = 0;
  for (int i = 0; i < s.repeat; ++i) {
    const auto start = std::chrono::steady_clock::now();
    rows = analysis::estimateForces(trial, profile, {}).rows.size();
    const std::chrono::duration<double> wall = std::chrono::steady_clock::now() - start;
    rates.push_back(static_cast<double>(rows) / wall.count());
  }
  report.add(measured("forces", "force estimate from a recording (both arms)", Spread::of(rates),
                      "rows/s",
                      fmt::format("2arm_physical_1.csv, {} rows of 241 columns, the file read "
                                  "included; {} runs",
                                  rows, s.repeat)));
}

}  // namespace bench
