#pragma once
// Single key presses from a terminal, read on their own thread (the paper's keyboard thread).

#include <atomic>
#include <deque>
#include <mutex>
#include <optional>
#include <thread>

namespace controller {

/// Reads characters from `fd` without waiting for Enter (raw mode on a terminal, restored when
/// destroyed) and queues them.
class TerminalKeys {
 public:
  explicit TerminalKeys(int fd);
  ~TerminalKeys();
  TerminalKeys(const TerminalKeys&) = delete;
  TerminalKeys& operator=(const TerminalKeys&) = delete;

  /// The oldest unread key, if any (never blocks).
  std::optional<char> next();

 private:
  void run();

  int fd_;
  bool restore_ = false;
  struct Saved;
  std::unique_ptr<Saved> saved_;
  std::mutex mutex_;
  std::deque<char> keys_;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

}  // namespace controller
