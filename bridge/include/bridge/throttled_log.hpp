#pragma once
// Logs a warning the first time it occurs and then at most once a second with a repeat count,
// so a 1 kHz stream of bad commands cannot flood the log.

#include <map>
#include <string>

namespace bridge {

/// Rate-limited warnings timed by the caller's clock. Messages that differ only in their numbers
/// (the text from the first digit on) share one budget.
class ThrottledLog {
 public:
  explicit ThrottledLog(double interval = 1.0) : interval_(interval) {}
  void warn(const std::string& message, double now);

 private:
  struct Seen {
    double last_logged;
    long suppressed;
  };
  double interval_;
  std::map<std::string, Seen> seen_;
};

}  // namespace bridge
