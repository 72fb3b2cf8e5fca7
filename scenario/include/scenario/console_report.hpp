#pragma once
// What the main job prints: a progress bar on a terminal, the per-ring table, the timing lines,
// a batch's per-run table, and the rectangle task's summary.

#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "scenario/peg_transfer_result.hpp"
#include "scenario/rectangle_task.hpp"
#include "scenario/run_progress.hpp"

namespace scenario {

/// A one-line bar redrawn in place on a terminal (at most 10 times a second); silent on
/// anything else, so logs and CI output stay clean.
class ProgressBar {
 public:
  /// `label` names the units ("transfers", "runs", "readings").
  ProgressBar(std::FILE* stream, std::string label);
  ~ProgressBar();
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  void show(const RunProgress& progress);
  /// Ends the line (once, if anything was drawn).
  void finish();

 private:
  std::FILE* stream_;
  std::string label_;
  bool enabled_;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point last_{};
};

/// The per-ring table of one run, then the totals line.
std::string ringTable(const PegTransferResult& result);
/// "simulated 85.9 s in 52.0 s of wall time: 1.65x real time; dynamic loop 1,710 Hz ..."
std::string timingLine(const RunTiming& timing);
/// One row per run (seed, rings placed, lost, times, rates) and the batch's totals.
std::string batchTable(const std::vector<PegTransferResult>& results);
/// The rectangle task's extents per arm, against the requested rectangle.
std::string rectangleSummary(const RectangleResult& result, const RectangleOptions& options);

}  // namespace scenario
