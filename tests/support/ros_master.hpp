#pragma once
// Test helpers for ROS: child processes killed by PID, and a private rosmaster on a free port
// with ROS_MASTER_URI, ROS_HOME and ROS_LOG_DIR pointing at a temp dir.

#include <sys/types.h>

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "test_files.hpp"

namespace test_support {

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

 private:
  pid_t pid_ = -1;
};

/// A free TCP port on localhost (bound once by the kernel, then released).
int freePort();

/// A rosmaster of this test process alone. Sets the ROS environment variables of this process
/// (inherited by every child) and waits until the master accepts connections.
class RosMaster {
 public:
  RosMaster();
  ~RosMaster();
  const std::string& uri() const { return uri_; }
  const std::filesystem::path& home() const { return dir_.path(); }

 private:
  TempDir dir_;
  std::string uri_;
  std::unique_ptr<ChildProcess> process_;
};

}  // namespace test_support
