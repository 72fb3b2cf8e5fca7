#pragma once
// Writing and reading the paper's recordings: rs (robot state) and ci (controller inputs) CSV
// files. Writers flush every row; readers accept every variant the reference lists, say which
// one they found, and reject bad files with the file, row and column at fault.

#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "bridge/raven_state.hpp"
#include "raven/arm.hpp"
#include "recording/gamepad_state.hpp"

namespace recording {

/// A recording that cannot be read: the message names the file and the row (1 = the header).
class RecordingError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Appends rows to a CSV file and flushes each one, so a crash loses nothing already written.
class CsvFile {
 public:
  /// Creates (truncates) `path` and writes `header`. Throws RecordingError if it cannot.
  CsvFile(const std::filesystem::path& path, const std::string& header);
  ~CsvFile();
  CsvFile(const CsvFile&) = delete;
  CsvFile& operator=(const CsvFile&) = delete;
  void writeLine(const std::string& line);
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
  std::FILE* file_ = nullptr;
};

/// `<name>_rs.csv`: one row per manual-loop iteration, times relative to the first row.
class RsWriter {
 public:
  explicit RsWriter(const std::filesystem::path& path);
  void write(const bridge::RavenStateSnapshot& state);
  /// One row already in rsColumnNames() order (time relative to the first row), e.g. a replay
  /// kept in memory.
  void writeRow(const std::vector<double>& values);
  std::size_t rows() const { return rows_; }
  const std::filesystem::path& path() const { return file_.path(); }

 private:
  CsvFile file_;
  std::size_t rows_ = 0;
  double t0_ = 0.0;
};

/// `<name>_ci.csv`: the 14 input columns, no index column.
class CiWriter {
 public:
  explicit CiWriter(const std::filesystem::path& path);
  void write(const GamepadState& pad);
  std::size_t rows() const { return rows_; }

 private:
  CsvFile file_;
  std::size_t rows_ = 0;
};

/// Reads a ci file: a header naming the 14 columns, then rows of 14 finite numbers.
std::vector<GamepadState> readCi(const std::filesystem::path& path);

/// Which rs variant a file is.
struct RsVariant {
  bool index_column = false;  ///< the unnamed leading column pandas writes
  std::size_t columns = 0;    ///< named columns
  bool legacy = false;        ///< Oct 2023: no mpos_d, grasp_d0..15 (238 columns)
  bool jpos_in_degrees = false;
  bool from_ambf = false;  ///< AMBF rows: offsets on jpos, NaN in the robot-only fields
  std::string describe() const;
};

/// An rs file in memory. jpos and jvel are converted to radians (metres) when the file had
/// degrees; empty fields are NaN.
/// One arm's row of a Raven-II recording down to its motors, in SI: joints and joint setpoints
/// (rad, m), motor angles and their setpoints (rad), motor velocities (rad/s), Tau (N m) and the
/// DAC commands (counts). raven2-actuation.md §1 gives the logged units this converts from.
struct ArmSignals {
  raven::ArmJoints joints, joint_setpoint, motor, motor_velocity, motor_setpoint, torque, dac;
};

struct RsRecording {
  std::filesystem::path path;
  RsVariant variant;
  std::vector<std::string> names;
  std::vector<std::vector<double>> rows;

  /// Column index of `name`; throws RecordingError naming the file when absent.
  std::size_t column(const std::string& name) const;
  double time(std::size_t row) const;
  /// jpos of `arm` in ArmJoints order, in the platform's own joint convention (AMBF rows: the
  /// recorder's +0.46 m insertion and +pi/4 roll offsets removed, the right jaws' sign restored).
  raven::ArmJoints joints(std::size_t row, raven::Arm arm) const;
  /// The physical robot's (or our twin's) signals of `arm` at `row`; throws RecordingError
  /// naming the file and a missing column.
  ArmSignals signals(std::size_t row, raven::Arm arm) const;
};

/// What readRs does with a NaN, infinite or impossible (beyond +-1e3 rad or m) joint position:
/// refuse the file (anything that will command a robot) or keep it as NaN (analysis, which
/// reports and skips such rows).
enum class NonFiniteJoints { Refuse, Keep };

/// Reads any rs variant. Throws RecordingError with the file and row on bad input (the time
/// column must always be finite).
RsRecording readRs(const std::filesystem::path& path,
                   NonFiniteJoints non_finite = NonFiniteJoints::Refuse);

}  // namespace recording
