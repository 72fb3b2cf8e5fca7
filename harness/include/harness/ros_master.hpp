#pragma once
// A private rosmaster on a free port, with ROS_MASTER_URI, ROS_HOME and ROS_LOG_DIR pointing at
// a temporary directory.

#include <memory>
#include <string>

#include "harness/child_process.hpp"
#include "harness/temp_dir.hpp"

namespace harness {

/// A rosmaster of this process alone. Sets the ROS environment variables of this process
/// (inherited by every child) and waits until the master accepts connections.
class RosMaster {
 public:
  RosMaster();
  ~RosMaster();
  const std::string& uri() const { return uri_; }
  const std::filesystem::path& home() const { return dir_.path(); }
  /// Kills the master (SIGKILL, as a crash would) and starts a new one on the same port, which
  /// knows nothing of what the old one had registered.
  void restart();

 private:
  void start();

  TempDir dir_;
  int port_;
  std::string uri_;
  std::unique_ptr<ChildProcess> process_;
};

}  // namespace harness
