#include "controller/terminal_keys.hpp"

#include <poll.h>
#include <termios.h>
#include <unistd.h>

#include <memory>

namespace controller {

/// The terminal's settings before raw mode.
struct TerminalKeys::Saved {
  termios settings;
};

TerminalKeys::TerminalKeys(int fd) : fd_(fd), saved_(std::make_unique<Saved>()) {
  if (isatty(fd_) && tcgetattr(fd_, &saved_->settings) == 0) {
    termios raw = saved_->settings;
    raw.c_lflag &= static_cast<tcflag_t>(~(ICANON | ECHO));
    raw.c_cc[VMIN] = 1;
    raw.c_cc[VTIME] = 0;
    restore_ = tcsetattr(fd_, TCSANOW, &raw) == 0;
  }
  thread_ = std::thread([this] { run(); });
}

TerminalKeys::~TerminalKeys() {
  stop_ = true;
  thread_.join();
  if (restore_) tcsetattr(fd_, TCSANOW, &saved_->settings);
}

std::optional<char> TerminalKeys::next() {
  std::lock_guard lock(mutex_);
  if (keys_.empty()) return std::nullopt;
  const char key = keys_.front();
  keys_.pop_front();
  return key;
}

void TerminalKeys::run() {
  while (!stop_) {
    pollfd p{fd_, POLLIN, 0};
    if (poll(&p, 1, 50) <= 0) continue;
    if (!(p.revents & POLLIN)) {
      if (p.revents & (POLLHUP | POLLERR | POLLNVAL)) return;  // the terminal went away
      continue;
    }
    char c = 0;
    if (read(fd_, &c, 1) != 1) return;
    std::lock_guard lock(mutex_);
    keys_.push_back(c);
  }
}

}  // namespace controller
