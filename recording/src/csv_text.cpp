#include "recording/csv_text.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include "common/file_problem.hpp"
#include "recording/recording_io.hpp"

namespace recording {

std::string rowWhere(const std::filesystem::path& path, std::size_t row) {
  return path.string() + ": row " + std::to_string(row);
}

std::vector<std::string> readCsvLines(const std::filesystem::path& path) {
  // A pipe or a device read as a recording could block or never end.
  if (const auto problem = common::fileProblem(path); !problem.empty()) {
    throw RecordingError(path.string() + ": " + problem);
  }
  std::ifstream in(path);
  if (!in) throw RecordingError(path.string() + ": cannot open");
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(line);
  }
  if (lines.empty()) throw RecordingError(path.string() + ": empty file (no header)");
  return lines;
}

std::vector<std::string> splitCsv(const std::string& line) {
  std::vector<std::string> fields;
  std::string field;
  std::istringstream in(line);
  while (std::getline(in, field, ',')) fields.push_back(field);
  if (!line.empty() && line.back() == ',') fields.emplace_back();
  return fields;
}

std::optional<double> parseCsvNumber(std::string text, bool empty_is_nan) {
  while (!text.empty() && (text.back() == '\r' || text.back() == ' ')) text.pop_back();
  while (!text.empty() && text.front() == ' ') text.erase(0, 1);
  if (text.empty()) {
    return empty_is_nan ? std::optional<double>(std::nan("")) : std::nullopt;
  }
  double value = 0.0;
  const char* begin = text.data();
  if (*begin == '+') ++begin;
  const auto [end, error] = std::from_chars(begin, text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

std::vector<std::vector<double>> readNumberRows(const std::filesystem::path& path,
                                                const std::vector<std::string>& lines,
                                                const std::vector<std::string>& names) {
  std::vector<std::vector<double>> rows;
  for (std::size_t r = 1; r < lines.size(); ++r) {
    if (lines[r].empty() && r + 1 == lines.size()) break;  // a final newline
    const auto fields = splitCsv(lines[r]);
    if (fields.size() != names.size()) {
      throw RecordingError(rowWhere(path, r + 1) + ": " + std::to_string(fields.size()) +
                           " columns, the header has " + std::to_string(names.size()) +
                           (r + 1 == lines.size() ? " (a truncated last line?)" : ""));
    }
    std::vector<double> values;
    values.reserve(fields.size());
    for (std::size_t c = 0; c < fields.size(); ++c) {
      const auto value = parseCsvNumber(fields[c], true);
      if (!value) {
        throw RecordingError(rowWhere(path, r + 1) + ", column '" + names[c] + "': '" + fields[c] +
                             "' is not a number");
      }
      values.push_back(*value);
    }
    rows.push_back(std::move(values));
  }
  return rows;
}

}  // namespace recording
