#include "scenario/ros/peg_transfer_over_ros.hpp"

#include <spdlog/spdlog.h>
#include <unistd.h>

#include <memory>
#include <stdexcept>

#include "bridge/ros/raven_ros_client.hpp"
#include "bridge/ros/ros_scene_perception.hpp"
#include "harness/child_process.hpp"
#include "raven/platform_profile.hpp"
#include "scenario/peg_layout.hpp"

namespace scenario::ros1 {

namespace {

/// The peg-transfer scene's namespace (raven_description's peg_transfer models): its objects'
/// topics.
constexpr const char* kSceneNamespace = "/peg_transfer/";

void refuseWhatANodeCannotTake(const PegTransferOptions& options) {
  if (options.randomize) {
    throw std::invalid_argument(
        "over ROS the twin node runs the scene file as it is: no --randomize");
  }
  if (options.assist != AssistMode::Off) {
    throw std::invalid_argument("the grasp assist acts inside the simulator: not over ROS");
  }
  if (options.observe) {
    throw std::invalid_argument("the viewer watches an in-process world: not over ROS");
  }
}

}  // namespace

std::filesystem::path builtTwinNode() {
  return RAVEN_TWIN_NODE;
}

std::vector<std::string> twinNodeCommand(const std::filesystem::path& program,
                                         const std::string& ns, const PegTransferOptions& options) {
  std::vector<std::string> argv{
      program.string(),
      "__ns:=" + ns,
      "__name:=twin",
      "--lock-step",
      "--no-crtk",
      "--launch",
      (options.launch_file.empty() ? raven::modelDirectory() / "peg_transfer" / "launch.yaml"
                                   : options.launch_file)
          .string()};
  argv.push_back("--actuation");
  argv.emplace_back(common::actuationWord(options.actuation));
  if (!options.calibration.empty()) {
    argv.push_back("--calibration");
    argv.push_back(options.calibration.string());
  }
  if (options.soft_body_sleep) argv.push_back("--soft-body-sleep");
  return argv;
}

PegTransferResult runPegTransferOverRos(const PegTransferOptions& options,
                                        const OverRosOptions& ros) {
  refuseWhatANodeCannotTake(options);
  std::unique_ptr<harness::ChildProcess> node;
  std::string ns = ros.robot_namespace;
  if (ns.empty()) {
    ns = "/peg_transfer_run_" + std::to_string(::getpid());
    const auto log = ros.node_log.empty() ? std::filesystem::temp_directory_path() /
                                                ("raven_twin_" + ns.substr(1) + ".log")
                                          : ros.node_log;
    const auto argv =
        twinNodeCommand(ros.twin_node.empty() ? builtTwinNode() : ros.twin_node, ns, options);
    spdlog::info("starting the twin node under {} (log: {})", ns, log.string());
    node = std::make_unique<harness::ChildProcess>(argv, log);
  }
  bridge::ros1::RosClientOptions client_options;
  client_options.robot_namespace = ns;
  client_options.lock_step = true;
  bridge::ros1::RavenRosClient robot(client_options);

  bridge::ros1::RosPerceptionOptions seeing;
  seeing.topic_namespace = kSceneNamespace;
  seeing.lock_step = true;
  seeing.objects.push_back(PegLayout::kBoard);
  for (const RingJob& job : PegLayout{}.jobs) seeing.objects.push_back(job.ring);
  bridge::ros1::RosScenePerception scene(seeing);

  PegTransferResult result = runPegTransferOn(robot, scene, options);
  if (node) node->stop();
  return result;
}

}  // namespace scenario::ros1
