#pragma once
// The disparity report on disk: every metric as JSON and CSV, the data behind each figure as
// CSV, and the figures themselves (PNG and an HTML page) drawn by analysis/report/draw_report.py.

#include <filesystem>
#include <string>
#include <vector>

#include "analysis/trial_set.hpp"

namespace analysis {

/// What the report's header says about how trials were aligned.
struct ReportSettings {
  std::string alignment = "row index";
  std::size_t scatter_points = 4000;  ///< per joint and factor in scatter.csv (evenly thinned)
};

/// Writes metrics.json, metrics.csv, correlations.csv, issues.csv, trajectories.csv,
/// scatter.csv and lowess.csv into `dir` (created). Throws std::runtime_error naming a file it
/// cannot write.
void writeReportData(const TrialSet& set, const ReportSettings& settings,
                     const std::filesystem::path& dir);

/// Pictures of the runs beside the recordings: the PNG snapshots and videos (.mp4, .mkv, .webm)
/// in the input folders (or the folders of input files), copied into `dir`/pictures and listed
/// in pictures.json; a PNG with a video's stem is that video's first frame (its poster).
/// Returns how many are listed. Throws std::runtime_error naming a file it cannot copy.
std::size_t writePictures(const std::vector<std::filesystem::path>& inputs,
                          const std::filesystem::path& dir);

/// Runs a drawing script (`/usr/bin/python3 script args...`; a path holding a quote is refused,
/// not passed to the shell). Returns an empty string on success, otherwise why the figures are
/// missing (the data files stay).
std::string runDrawScript(const std::filesystem::path& script,
                          const std::vector<std::filesystem::path>& args);

/// Runs the drawing script on `dir` (PNG figures and index.html); runDrawScript's answer.
std::string drawFigures(const std::filesystem::path& dir);

}  // namespace analysis
