#include "recording/recording_io.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "recording/csv_text.hpp"
#include "recording/recording_format.hpp"

namespace recording {

namespace {

std::string joinHeader(const std::vector<std::string>& names, bool index_column) {
  std::string header = index_column ? "," : "";
  for (std::size_t i = 0; i < names.size(); ++i) header += (i ? "," : "") + names[i];
  return header;
}

}  // namespace

CsvFile::CsvFile(const std::filesystem::path& path, const std::string& header) : path_(path) {
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
  file_ = std::fopen(path.c_str(), "w");
  if (!file_) throw RecordingError(path.string() + ": cannot create");
  writeLine(header);
}

CsvFile::~CsvFile() {
  if (file_) std::fclose(file_);
}

void CsvFile::writeLine(const std::string& line) {
  std::fputs(line.c_str(), file_);
  std::fputc('\n', file_);
  std::fflush(file_);
}

RsWriter::RsWriter(const std::filesystem::path& path)
    : file_(path, joinHeader(rsColumnNames(), true)) {}

void RsWriter::write(const bridge::RavenStateSnapshot& state) {
  if (rows_ == 0) t0_ = state.time;
  writeRow(rsRow(state, t0_));
}

void RsWriter::writeRow(const std::vector<double>& values) {
  std::string line = std::to_string(rows_);
  for (std::size_t i = 0; i < values.size(); ++i) {
    line += ',' + formatRsValue(values[i], /*round_to_micro=*/i != 0);
  }
  file_.writeLine(line);
  ++rows_;
}

CiWriter::CiWriter(const std::filesystem::path& path)
    : file_(path, [] {
        std::string header;
        for (auto name : GamepadState::ciColumnNames()) {
          header += (header.empty() ? "" : ",") + std::string(name);
        }
        return header;
      }()) {}

void CiWriter::write(const GamepadState& pad) {
  std::string line;
  for (double v : pad.toCiRow()) {
    line += (line.empty() ? "" : ",") + formatRsValue(v, /*round_to_micro=*/false);
  }
  file_.writeLine(line);
  ++rows_;
}

std::vector<GamepadState> readCi(const std::filesystem::path& path) {
  const auto lines = readCsvLines(path);
  const auto header = splitCsv(lines[0]);
  const auto& expected = GamepadState::ciColumnNames();
  if (header.size() != expected.size()) {
    throw RecordingError(rowWhere(path, 1) + ": the header has " + std::to_string(header.size()) +
                         " columns; a ci file has 14 (" + std::string(expected[0]) + ", ..., " +
                         std::string(expected.back()) + ")");
  }
  for (std::size_t c = 0; c < expected.size(); ++c) {
    if (header[c] != expected[c]) {
      throw RecordingError(rowWhere(path, 1) + ": column " + std::to_string(c + 1) + " is '" +
                           header[c] + "', expected '" + std::string(expected[c]) + "'");
    }
  }
  std::vector<GamepadState> pads;
  for (std::size_t r = 1; r < lines.size(); ++r) {
    if (lines[r].empty() && r + 1 == lines.size()) break;  // a final newline
    const auto fields = splitCsv(lines[r]);
    if (fields.size() != expected.size()) {
      throw RecordingError(rowWhere(path, r + 1) + ": " + std::to_string(fields.size()) +
                           " columns, expected 14" +
                           (r + 1 == lines.size() ? " (a truncated last line?)" : ""));
    }
    std::array<double, GamepadState::kCiColumns> values{};
    for (std::size_t c = 0; c < fields.size(); ++c) {
      const auto value = parseCsvNumber(fields[c], false);
      if (!value || !std::isfinite(*value)) {
        throw RecordingError(rowWhere(path, r + 1) + ", column '" + std::string(expected[c]) +
                             "': '" + fields[c] + "' is not a finite number");
      }
      values[c] = *value;
    }
    pads.push_back(GamepadState::fromCiRow(values));
  }
  // A replay of nothing would wait for its first row forever.
  if (pads.empty()) throw RecordingError(path.string() + ": no rows after the header");
  return pads;
}

std::string RsVariant::describe() const {
  std::ostringstream out;
  out << columns << " named columns" << (index_column ? " after an index column" : "")
      << (legacy ? " (the Oct 2023 layout: no mpos_d, 16 grasp_d)" : "") << ", jpos in "
      << (jpos_in_degrees ? "degrees (converted)" : "radians and metres") << ", "
      << (from_ambf ? "AMBF rows (recorder offsets on jpos, robot fields empty)"
                    : "physical-robot rows");
  return out.str();
}

std::size_t RsRecording::column(const std::string& name) const {
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (names[i] == name) return i;
  }
  throw RecordingError(path.string() + ": no column '" + name + "'");
}

double RsRecording::time(std::size_t row) const {
  return rows.at(row)[column("time")];
}

raven::ArmJoints RsRecording::joints(std::size_t row, raven::Arm arm) const {
  raven::ArmJoints q;
  for (int i = 0; i < raven::kJointCount; ++i) {
    q(i) = rows.at(row)[column("jpos" + std::to_string(bridge::ravenStateIndex(arm, i)))];
  }
  if (variant.from_ambf) {  // undo the AMBF recorder's [j1, j2, j3 + 0.46, 0, j4 + pi/4, ...]
    q(raven::kInsertion) -= 0.46;
    q(raven::kRoll) -= M_PI / 4.0;
    if (arm == raven::Arm::Right) {
      q(raven::kJaw1) = -q(raven::kJaw1);
      q(raven::kJaw2) = -q(raven::kJaw2);
    }
  }
  return q;
}

ArmSignals RsRecording::signals(std::size_t row, raven::Arm arm) const {
  constexpr double kRadiansPerDegree = M_PI / 180.0;
  const auto& r = rows.at(row);
  auto read = [&](const char* prefix, double scale) {
    raven::ArmJoints v;
    for (int i = 0; i < raven::kJointCount; ++i) {
      v(i) = scale * r[column(prefix + std::to_string(bridge::ravenStateIndex(arm, i)))];
    }
    return v;
  };
  // jpos_d is logged in degrees, its insertion in metres x 180/pi: one scale for all.
  return {joints(row, arm),
          read("jpos_d", kRadiansPerDegree),
          read("mpos", kRadiansPerDegree),
          read("mvel", kRadiansPerDegree),
          read("mpos_d", kRadiansPerDegree),
          read("Tau", 1.0),
          read("dac_vals", 1.0)};
}

RsRecording readRs(const std::filesystem::path& path, NonFiniteJoints non_finite) {
  const auto lines = readCsvLines(path);
  RsRecording rec;
  rec.path = path;
  rec.names = splitCsv(lines[0]);
  rec.variant.index_column = !rec.names.empty() && rec.names[0].empty();
  rec.variant.columns = rec.names.size() - (rec.variant.index_column ? 1 : 0);
  // Two columns of one name: which one a reader takes would be a guess.
  for (std::size_t c = 0; c < rec.names.size(); ++c) {
    if (rec.names[c].empty()) continue;  // the index column has none
    if (std::find(rec.names.begin(), rec.names.begin() + static_cast<long>(c), rec.names[c]) !=
        rec.names.begin() + static_cast<long>(c)) {
      throw RecordingError(rowWhere(path, 1) + ": column " + std::to_string(c + 1) +
                           " is a second '" + rec.names[c] + "' column");
    }
  }
  std::vector<std::string> required{"time"};
  for (int j = 0; j < 16; ++j) required.push_back("jpos" + std::to_string(j));
  for (const auto& name : required) {
    if (std::find(rec.names.begin(), rec.names.end(), name) == rec.names.end()) {
      throw RecordingError(rowWhere(path, 1) + ": no '" + name +
                           "' column; this is not an rs file");
    }
  }
  const auto has = [&](const std::string& n) {
    return std::find(rec.names.begin(), rec.names.end(), n) != rec.names.end();
  };
  rec.variant.legacy = !has("mpos_d0") && has("grasp_d15");
  rec.rows = readNumberRows(path, lines, rec.names);
  if (rec.rows.empty()) throw RecordingError(path.string() + ": no rows after the header");
  // No joint of any robot reads beyond this (rad or m: 160 turns, a kilometre); a value past it
  // is a broken sample, and sums over it overflow.
  constexpr double kLargestJoint = 1e3;
  for (const auto& name : required) {
    const bool joint = name != "time";
    const std::size_t c = rec.column(name);
    for (std::size_t r = 0; r < rec.rows.size(); ++r) {
      double& value = rec.rows[r][c];
      const bool broken = !std::isfinite(value) || (joint && std::abs(value) > kLargestJoint);
      if (!broken) continue;
      if (joint && non_finite == NonFiniteJoints::Keep) {
        value = std::numeric_limits<double>::quiet_NaN();  // reported and skipped as NaN
        continue;
      }
      throw RecordingError(rowWhere(path, r + 2) + ", column '" + name + "': " +
                           (std::isfinite(value) ? std::to_string(value) + " is beyond +-1e3"
                                                 : std::string("not a finite number")));
    }
  }
  if (non_finite == NonFiniteJoints::Refuse) {
    // A replay waits for each row's time: it must come after the last, and not so long after
    // that the robot would idle for it (no recording of ours pauses for a minute).
    constexpr double kLongestGap = 60.0;
    const std::size_t time = rec.column("time");
    for (std::size_t r = 1; r < rec.rows.size(); ++r) {
      const double gap = rec.rows[r][time] - rec.rows[r - 1][time];
      if (!(gap > 0.0) || gap > kLongestGap) {
        throw RecordingError(rowWhere(path, r + 2) +
                             ", column 'time': " + std::to_string(rec.rows[r][time]) + " s is " +
                             (gap > 0.0 ? "more than a minute after" : "not after") +
                             " the row before (" + std::to_string(rec.rows[r - 1][time]) +
                             " s); a replay would wait for it");
      }
    }
  }
  // An insertion of more than 2 "m" is degrees; AMBF rows leave the robot-only fields empty.
  const std::size_t insertion = rec.column("jpos2");
  const auto first_insertion = std::find_if(rec.rows.begin(), rec.rows.end(), [&](const auto& row) {
    return std::isfinite(row[insertion]);
  });
  rec.variant.jpos_in_degrees =
      first_insertion != rec.rows.end() && std::abs((*first_insertion)[insertion]) > 2.0;
  rec.variant.from_ambf = has("runlevel") && std::isnan(rec.rows[0][rec.column("runlevel")]);
  if (rec.variant.jpos_in_degrees) {
    for (auto& row : rec.rows) {
      for (std::size_t c = 0; c < rec.names.size(); ++c) {
        if (rec.names[c].rfind("jpos", 0) == 0 && rec.names[c].rfind("jpos_d", 0) != 0) {
          row[c] *= M_PI / 180.0;
        }
        if (rec.names[c].rfind("jvel", 0) == 0) row[c] *= M_PI / 180.0;
      }
    }
  }
  return rec;
}

}  // namespace recording
