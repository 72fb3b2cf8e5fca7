#include "recording/cf_recording.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "recording/csv_text.hpp"

namespace recording {

namespace {

constexpr std::array<const char*, 11> kPerArm{"fx",          "fy",
                                              "fz",          "tx",
                                              "ty",          "tz",
                                              "jaw1_normal", "jaw1_friction",
                                              "jaw2_normal", "jaw2_friction",
                                              "contacts"};

std::vector<double> armValues(const std::optional<bridge::GrasperForces>& cf) {
  if (!cf) return std::vector<double>(kPerArm.size(), std::nan(""));
  const auto& j = cf->jaws;
  return {cf->force.x(),
          cf->force.y(),
          cf->force.z(),
          cf->torque.x(),
          cf->torque.y(),
          cf->torque.z(),
          j[0].normal.norm(),
          j[0].friction.norm(),
          j[1].normal.norm(),
          j[1].friction.norm(),
          static_cast<double>(j[0].contacts + j[1].contacts)};
}

}  // namespace

std::filesystem::path cfPathFor(const std::filesystem::path& rs_path) {
  std::string name = rs_path.filename().string();
  const std::string rs = "_rs.csv";
  if (name.ends_with(rs)) {
    name.replace(name.size() - rs.size(), rs.size(), "_cf.csv");
  } else {
    name = rs_path.stem().string() + "_cf.csv";
  }
  return rs_path.parent_path() / name;
}

const std::vector<std::string>& CfWriter::columnNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out{"time"};
    for (const char* arm : {"left_", "right_"}) {
      for (const char* column : kPerArm) out.push_back(std::string(arm) + column);
    }
    return out;
  }();
  return names;
}

CfWriter::CfWriter(const std::filesystem::path& path)
    : file_(path, fmt::format("{}", fmt::join(columnNames(), ","))) {}

void CfWriter::write(double time, const raven::PerArm<std::optional<bridge::GrasperForces>>& arms) {
  if (rows_ == 0) t0_ = time;
  std::string line = fmt::format("{:.6f}", time - t0_);
  for (const auto& arm : arms) {
    for (double v : armValues(arm)) line += fmt::format(",{:.6g}", v);
  }
  file_.writeLine(line);
  ++rows_;
}

std::size_t CfRecording::column(const std::string& name) const {
  const auto& names = CfWriter::columnNames();
  const auto it = std::find(names.begin(), names.end(), name);
  if (it == names.end()) throw RecordingError(path.string() + ": no cf column '" + name + "'");
  return static_cast<std::size_t>(it - names.begin());
}

CfRecording readCf(const std::filesystem::path& path) {
  const auto lines = readCsvLines(path);
  if (splitCsv(lines[0]) != CfWriter::columnNames()) {
    throw RecordingError(rowWhere(path, 1) + ": not a cf file's header (" +
                         fmt::format("{}", fmt::join(CfWriter::columnNames(), ",")) + ")");
  }
  return {path, readNumberRows(path, lines, CfWriter::columnNames())};
}

}  // namespace recording
