#include "study/trial_events.hpp"

#include <fmt/format.h>

#include <cmath>
#include <fstream>

namespace study {

EventLog::EventLog(const std::filesystem::path& path) : file_(path, "time,event,arm,value") {}

void EventLog::add(double time, std::string_view name, int arm, double value) {
  file_.writeLine(fmt::format("{:.4f},{},{},{:.6g}", time, name, arm, value));
  events_.push_back({time, std::string(name), arm, value});
}

std::vector<TrialEvent> readEvents(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw recording::RecordingError(path.string() + ": cannot open");
  std::string line;
  std::getline(in, line);
  if (line != "time,event,arm,value") {
    throw recording::RecordingError(path.string() + ":1: not an events file (header '" + line +
                                    "')");
  }
  std::vector<TrialEvent> out;
  for (int row = 2; std::getline(in, line); ++row) {
    if (line.empty()) continue;
    const auto bad = [&](const char* what) {
      return recording::RecordingError(fmt::format("{}:{}: {}", path.string(), row, what));
    };
    std::vector<std::string> fields;
    for (std::size_t start = 0;;) {
      const std::size_t comma = line.find(',', start);
      fields.push_back(line.substr(start, comma - start));
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
    if (fields.size() != 4) throw bad("expected 4 fields (time,event,arm,value)");
    TrialEvent e;
    e.name = fields[1];
    try {
      e.time = std::stod(fields[0]);
      e.arm = std::stoi(fields[2]);
      e.value = std::stod(fields[3]);
    } catch (const std::exception&) {
      throw bad("time, arm and value must be numbers");
    }
    if (e.name.empty()) throw bad("an event needs a name");
    if (!std::isfinite(e.time)) throw bad("the time must be finite");
    out.push_back(e);
  }
  return out;
}

}  // namespace study
