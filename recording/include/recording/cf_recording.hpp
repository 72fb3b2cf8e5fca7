#pragma once
// `<name>_cf.csv`: the graspers' contact forces (measured_cf) beside an rs recording, one row
// per manual-loop iteration, for platforms that can tell them (the twin; the physical Raven-II
// has no force sensing and writes none).

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "bridge/grasper_forces.hpp"
#include "recording/recording_io.hpp"

namespace recording {

/// The cf file that belongs to the rs file `rs_path` (`x_rs.csv` -> `x_cf.csv`).
std::filesystem::path cfPathFor(const std::filesystem::path& rs_path);

/// A cf file in memory: the writer's columns, one row of numbers per iteration (NaN where an arm
/// has no forces).
struct CfRecording {
  std::filesystem::path path;
  std::vector<std::vector<double>> rows;

  /// Column index of `name` (CfWriter::columnNames()); throws RecordingError naming the file.
  std::size_t column(const std::string& name) const;
};

/// Reads a cf file; throws RecordingError naming the file and row on a header that is not the
/// writer's, a field that is not a number or a row of the wrong width.
CfRecording readCf(const std::filesystem::path& path);

/// Writes cf rows: time from the first row, then per arm (left_, right_) the total force and
/// torque (N, N m, the platform's world frame), each jaw's normal and friction force magnitudes
/// (N) and its contact count. An arm without forces writes nan.
class CfWriter {
 public:
  explicit CfWriter(const std::filesystem::path& path);
  void write(double time, const raven::PerArm<std::optional<bridge::GrasperForces>>& arms);
  std::size_t rows() const { return rows_; }
  const std::filesystem::path& path() const { return file_.path(); }

  static const std::vector<std::string>& columnNames();

 private:
  CsvFile file_;
  std::size_t rows_ = 0;
  double t0_ = 0.0;
};

}  // namespace recording
