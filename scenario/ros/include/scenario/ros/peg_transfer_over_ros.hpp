#pragma once
// The main job over ROS 1: the same peg transfer (runPegTransferOn) driven through
// RavenRosClient in lock-step, seeing the rings through the twin node's AMBF object topics. It
// starts raven_twin_node in its own process with the run's scene, or uses a node already
// serving in lock-step. Needs initRos() and a master.

#include <filesystem>
#include <string>

#include "scenario/peg_transfer.hpp"

namespace scenario::ros1 {

/// Where the robot is.
struct OverRosOptions {
  /// A twin node already serving the peg-transfer scene in lock-step under this namespace; empty:
  /// start one (in a fresh namespace) and stop it after the run.
  std::string robot_namespace;
  /// The raven_twin_node program to start (default: the one built with this one).
  std::filesystem::path twin_node;
  /// Where a started node logs (default: a file in the temp directory, named in the log).
  std::filesystem::path node_log;
};

/// The raven_twin_node built alongside this program.
std::filesystem::path builtTwinNode();

/// The node's command line for a run with `options` (scene, actuation and sleep as the
/// in-process run has them) under namespace `ns`.
std::vector<std::string> twinNodeCommand(const std::filesystem::path& program,
                                         const std::string& ns, const PegTransferOptions& options);

/// Runs the job once over ROS. Throws std::invalid_argument for options a node cannot take
/// (a randomised scene, the grasp assist, an observer), std::runtime_error when the robot or
/// the rings' topics are not found.
PegTransferResult runPegTransferOverRos(const PegTransferOptions& options,
                                        const OverRosOptions& ros);

}  // namespace scenario::ros1
