#include "study/trial_events.hpp"

#include <fmt/format.h>

#include <cmath>

#include "recording/csv_text.hpp"

namespace study {

namespace {

constexpr const char* kHeader = "time,event,arm,value";

}  // namespace

EventLog::EventLog(const std::filesystem::path& path) : file_(path, kHeader) {}

void EventLog::add(double time, std::string_view name, int arm, double value) {
  file_.writeLine(fmt::format("{:.4f},{},{},{:.6g}", time, name, arm, value));
  events_.push_back({time, std::string(name), arm, value});
}

std::vector<TrialEvent> readEvents(const std::filesystem::path& path) {
  const std::vector<std::string> lines = recording::readCsvLines(path);
  if (lines[0] != kHeader) {
    throw recording::RecordingError(recording::rowWhere(path, 1) + ": not an events file (" +
                                    kHeader + ")");
  }
  std::vector<TrialEvent> out;
  for (std::size_t r = 1; r < lines.size(); ++r) {
    if (lines[r].empty()) continue;
    const auto bad = [&](const char* what) {
      return recording::RecordingError(recording::rowWhere(path, r + 1) + ": " + what);
    };
    const std::vector<std::string> fields = recording::splitCsv(lines[r]);
    if (fields.size() != 4) throw bad("expected 4 fields (time,event,arm,value)");
    const auto time = recording::parseCsvNumber(fields[0], false);
    const auto arm = recording::parseCsvNumber(fields[2], false);
    const auto value = recording::parseCsvNumber(fields[3], false);
    if (!time || !std::isfinite(*time)) throw bad("the time must be a finite number");
    if (!arm || (*arm != -1.0 && *arm != 0.0 && *arm != 1.0)) throw bad("the arm is -1, 0 or 1");
    if (!value) throw bad("the value must be a number");
    if (fields[1].empty()) throw bad("an event needs a name");
    out.push_back({*time, fields[1], static_cast<int>(*arm), *value});
  }
  return out;
}

}  // namespace study
