#pragma once
// A trial's events beside its recordings (`events.csv`): when it began and ended, targets
// shown, entered, left and reached, rings lifted, placed and dropped, tool-board contacts, and
// the controller's joint-limit clamps and velocity-cap splits. One flushed row per event.

#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "recording/recording_io.hpp"

namespace study {

/// One row: simulated time (s from the trial's start), the event, its arm (-1: none; 0 left,
/// 1 right) and a value (a target's index, a ring's number, a force), or NaN.
struct TrialEvent {
  double time = 0.0;
  std::string name;
  int arm = -1;
  double value = 0.0;
};

/// Appends events to a trial's events.csv.
class EventLog {
 public:
  explicit EventLog(const std::filesystem::path& path);
  void add(double time, std::string_view name, int arm = -1, double value = 0.0);
  const std::vector<TrialEvent>& events() const { return events_; }

 private:
  recording::CsvFile file_;
  std::vector<TrialEvent> events_;
};

/// Reads an events.csv; throws recording::RecordingError naming the file and row.
std::vector<TrialEvent> readEvents(const std::filesystem::path& path);

}  // namespace study
