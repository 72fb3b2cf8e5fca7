#pragma once
// Programs started with fork/exec, their output in a log file, stopped by PID; free TCP ports.

#include <sys/types.h>

#include <filesystem>
#include <string>
#include <vector>

namespace harness {

/// A program started with fork/exec, its output in `log_file`; stopped when destroyed.
class ChildProcess {
 public:
  ChildProcess(const std::vector<std::string>& argv, const std::filesystem::path& log_file);
  ~ChildProcess();
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  pid_t pid() const { return pid_; }
  /// SIGINT, then SIGKILL if it has not exited within `grace` seconds; reaps it.
  void stop(double grace = 5.0);
  /// SIGKILL at once (a crash, a pulled cable); reaps it.
  void kill();
  /// Waits up to `timeout` wall seconds for the program to end; its exit code, or -1 if it had
  /// to be killed.
  int wait(double timeout);
  /// The running program's peak resident set size so far (KiB); -1 once it has ended.
  long peakResidentKiB() const;

 private:
  pid_t pid_ = -1;
};

/// A free TCP port on localhost (bound once by the kernel, then released).
int freePort();

}  // namespace harness
