#pragma once
// Logs a warning the first time its kind occurs and then at most once a second with a repeat
// count, so a 1 kHz stream of bad commands cannot flood the log.

#include <map>
#include <string>

namespace bridge {

/// Rate-limited warnings timed by the caller's clock, one budget per kind: a key from a bounded
/// set the caller chooses (e.g. "refused servo_jp left: joint would jump"), never a sender's
/// text. Messages are logged escaped and cut short, as they may carry a sender's text.
class ThrottledLog {
 public:
  explicit ThrottledLog(double interval = 1.0) : interval_(interval) {}
  void warn(const std::string& kind, const std::string& message, double now);
  /// A kind for messages of our own making that differ only in their numbers and names: the
  /// text up to its first digit or quote.
  static std::string kindOf(const std::string& own_message);

 private:
  struct Seen {
    double last_logged;
    long suppressed;
  };
  double interval_;
  std::map<std::string, Seen> seen_;
};

}  // namespace bridge
