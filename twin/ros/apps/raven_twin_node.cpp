// raven_twin_node: the twin served on the physical Raven-II's ROS topics, with the robot's
// motor-level actuation (its raven_state carries motor angles, torques and DAC commands), so the
// physical path can be exercised without a robot.

#include <spdlog/spdlog.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <optional>
#include <sstream>
#include <vector>

#include "bridge/ros/master_watch.hpp"
#include "bridge/ros/raven_ros_server.hpp"
#include "bridge/ros/ros_runtime.hpp"
#include "common/actuation_flag.hpp"
#include "common/number_checks.hpp"
#include "twin/calibration_profile.hpp"
#include "twin/ros/ambf_object_topics.hpp"
#include "twin/ros/camera_topics.hpp"
#include "twin/twin_platform.hpp"

namespace {

/// Everything the command line sets.
struct NodeSettings {
  twin::TwinOptions twin;
  std::string launch = twin.launch_file.string();
  bool ambf_model = false;
  common::ActuationKind actuation = common::ActuationKind::Motors;  // ideal with AMBF's model
  std::string calibration;
  bool soft_body_sleep = false;
  bridge::ros1::RosServerOptions server;
  bool no_arm_swap = false;
  bridge::ros1::CrtkFaceOptions crtk;
  std::vector<std::string> crtk_arms{crtk.arm_names.begin(), crtk.arm_names.end()};
  bool no_crtk = false;
  double duration = 0.0;
  twin::ros1::CameraTopicOptions cameras;
  std::string camera_size = "128x96";
};

void addOptions(CLI::App& app, NodeSettings& s) {
  app.add_option("--launch", s.launch, "launch file of the scene with the robot")
      ->check(CLI::ExistingFile);
  app.add_option("--profile", s.twin.profile, "platform profile: physical, ambf or a YAML file");
  app.add_flag("--ambf-model", s.ambf_model,
               "the launch file holds AMBF's blender-raven2.yaml (AMBF joint names)");
  app.add_flag("--strict", s.twin.load.strict,
               "refuse model files AMBF would load with warnings (unknown keys, missing meshes)");
  common::addActuationFlag(app, s.actuation);
  app.add_option("--calibration", s.calibration,
                 "the actuation fitted by raven_calibrate (YAML; default: "
                 "twin/config/raven2_calibration.yaml)")
      ->check(CLI::ExistingFile);
  app.add_flag("--soft-body-sleep", s.soft_body_sleep,
               "resting soft bodies sleep (as raven_peg_transfer runs them), whatever the world "
               "file says");
  app.add_flag("--lock-step", s.server.lock_step,
               "run on the simulated clock, one step per client request (raven_twin/step)");
  app.add_flag("--no-arm-swap", s.no_arm_swap,
               "publish each arm on its own measured_js (upstream swaps them: arm1 = green)");
  app.add_option("--command-wait", s.server.command_wait,
                 "lock-step: wall seconds a step waits for the commands it names before it is "
                 "refused")
      ->check(common::kFinitePositive);
  app.add_option("--crtk-namespace", s.crtk.ros_namespace,
                 "namespace of the standard CRTK face, relative to the node's (absolute with a "
                 "leading /)")
      ->capture_default_str();
  app.add_option("--crtk-arms", s.crtk_arms,
                 "the standard CRTK face's names of the gold (left) and green (right) arm, e.g. "
                 "PSM1 PSM2")
      ->expected(2)
      ->capture_default_str();
  app.add_flag("--no-crtk", s.no_crtk, "serve the robot's own topics only, no standard CRTK face");
  app.add_option("--cameras", s.cameras.views,
                 "the peg-transfer scene's views to render and publish on "
                 "cameras/<view>/image_raw (sensor_msgs/Image): overview, left-task, right-task, "
                 "grasper-left, grasper-right")
      ->delimiter(',');
  app.add_option("--camera-size", s.camera_size, "the cameras' images, WxH")->capture_default_str();
  app.add_option("--camera-rate", s.cameras.rate, "the cameras' frames per second of twin time")
      ->check(common::kFinitePositive)
      ->capture_default_str();
  app.add_flag("--camera-depth", s.cameras.depth,
               "each view's depth image too, as an RGB-D camera's driver publishes it: "
               "cameras/<view>/depth/image_raw (sensor_msgs/Image, 32FC1, m along the axis)");
  app.add_option("--depth-noise", s.cameras.depth_noise,
                 "the depth read as a stereo RGB-D camera reads it: its RMS error at 1 m (m; it "
                 "grows as the depth squared), 0: exact")
      ->check(common::kFiniteNonNegative)
      ->capture_default_str();
  app.add_option("--depth-scale", s.cameras.depth_scale, "... and its scale bias (a factor)")
      ->check(common::kFinitePositive)
      ->capture_default_str();
  app.add_option("--depth-baseline", s.cameras.depth_baseline,
                 "... and its baseline (m): no reading where only one imager sees")
      ->check(common::kFiniteNonNegative)
      ->capture_default_str();
  app.add_option("--duration", s.duration,
                 "stop after this much platform time (s); 0: run until "
                 "interrupted")
      ->check(common::kFiniteNonNegative);
}

/// The twin the settings ask for: its scene, clock, bindings and actuation.
twin::TwinOptions twinOptionsOf(const NodeSettings& s) {
  twin::TwinOptions twin = s.twin;
  twin.launch_file = s.launch;
  twin.clock = s.server.lock_step ? bridge::ClockKind::Simulated : bridge::ClockKind::Wall;
  if (s.ambf_model) twin.bindings = twin::ArmBindings::ambfRaven();
  if (s.soft_body_sleep) {
    twin.adjust_scene = [](ambf_like::SceneSpec& scene) {
      scene.world.soft_body_sleep.enabled = true;
    };
  }
  // The motor model is the cable-driven robot's: in its joint convention, on our model.
  if (s.actuation == common::ActuationKind::Motors && !s.ambf_model && twin.profile == "physical") {
    (s.calibration.empty() ? twin::CalibrationProfile::shipped()
                           : twin::CalibrationProfile::load(s.calibration))
        .applyTo(twin);
  }
  return twin;
}

/// "WxH" into the options' size; throws std::invalid_argument naming the flag.
void readCameraSize(const std::string& text, twin::ros1::CameraTopicOptions& cameras) {
  char x = 0;
  std::istringstream in(text);
  if (!(in >> cameras.width >> x >> cameras.height) || x != 'x' || !in.eof()) {
    throw std::invalid_argument("--camera-size is WxH (e.g. 128x96), not '" + text + "'");
  }
}

/// Seconds since the epoch: the stamps of a node on the wall clock, as a camera driver's.
double wallStamp() {
  return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
}

}  // namespace

int main(int argc, char** argv) {
  bridge::ros1::initRos(argc, argv, "raven_twin");  // takes ROS remappings out of argv
  CLI::App app{"The Raven-II twin on the physical robot's ROS 1 topics."};
  NodeSettings s;
  addOptions(app, s);
  CLI11_PARSE(app, argc, argv);

  try {
    const twin::TwinOptions twin = twinOptionsOf(s);
    bridge::ros1::RosServerOptions server = s.server;
    server.arm_swap = !s.no_arm_swap;
    twin::TwinPlatform platform(twin);
    bridge::ros1::CrtkFaceOptions crtk = s.crtk;
    if (!s.no_crtk) {
      std::copy(s.crtk_arms.begin(), s.crtk_arms.end(), crtk.arm_names.begin());
      crtk.profile = platform.core().profile();
      server.crtk = crtk;
    }
    // The scene's bodies, sensors and actuators on AMBF's topics, served after every cycle.
    twin::ros1::AmbfObjectTopics objects(platform.world(), server.lock_step);
    std::optional<twin::ros1::CameraTopics> cameras;
    if (!s.cameras.views.empty()) {
      readCameraSize(s.camera_size, s.cameras);
      cameras.emplace(platform.world(), s.cameras);
    }
    server.after_cycle = [&] {
      objects.update(platform.now());
      if (cameras) {
        cameras->update(platform.world(), platform.now(),
                        server.lock_step ? platform.now() : wallStamp());
      }
    };
    bridge::ros1::RavenRosServer ros_server(platform, "", server);
    const bridge::ros1::MasterWatch master_watch;  // registers again with a restarted master
    spdlog::info("raven_twin: {} on {} ({}, {} clock, arm swap {}, standard CRTK {})",
                 twin.motors ? "the twin (motor-level actuation)" : "the twin (ideal servos)",
                 bridge::ros1::masterUri(), twin.profile,
                 server.lock_step ? "lock-step simulated" : "wall", server.arm_swap ? "on" : "off",
                 s.no_crtk ? "off"
                           : "under " + crtk.ros_namespace + "/{" + crtk.arm_names[0] + "," +
                                 crtk.arm_names[1] + "}");
    ros_server.spin(s.duration);
  } catch (const std::exception& e) {
    spdlog::error("{}", e.what());
    return 1;
  }
  return 0;
}
