// raven_twin_node: the twin served on the physical Raven-II's ROS topics, with the robot's
// motor-level actuation (its raven_state carries motor angles, torques and DAC commands), so the
// physical path can be exercised without a robot.

#include <spdlog/spdlog.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <filesystem>
#include <vector>

#include "bridge/ros/master_watch.hpp"
#include "bridge/ros/raven_ros_server.hpp"
#include "bridge/ros/ros_runtime.hpp"
#include "common/actuation_flag.hpp"
#include "twin/calibration_profile.hpp"
#include "twin/ros/ambf_object_topics.hpp"
#include "twin/twin_platform.hpp"

int main(int argc, char** argv) {
  bridge::ros1::initRos(argc, argv, "raven_twin");  // takes ROS remappings out of argv

  CLI::App app{"The Raven-II twin on the physical robot's ROS 1 topics."};
  twin::TwinOptions twin;
  std::string launch = twin.launch_file.string();
  app.add_option("--launch", launch, "launch file of the scene with the robot")
      ->check(CLI::ExistingFile);
  app.add_option("--profile", twin.profile, "platform profile: physical, ambf or a YAML file");
  bool ambf_model = false;
  app.add_flag("--ambf-model", ambf_model,
               "the launch file holds AMBF's blender-raven2.yaml (AMBF joint names)");
  app.add_flag("--strict", twin.load.strict,
               "refuse model files AMBF would load with warnings (unknown keys, missing meshes)");
  common::ActuationKind actuation =
      common::ActuationKind::Motors;  // ideal always with AMBF's model
  common::addActuationFlag(app, actuation);
  std::string calibration;
  app.add_option("--calibration", calibration,
                 "the actuation fitted by raven_calibrate (YAML; default: "
                 "twin/config/raven2_calibration.yaml)")
      ->check(CLI::ExistingFile);
  bool soft_body_sleep = false;
  app.add_flag("--soft-body-sleep", soft_body_sleep,
               "resting soft bodies sleep (as raven_peg_transfer runs them), whatever the world "
               "file says");
  bridge::ros1::RosServerOptions server;
  app.add_flag("--lock-step", server.lock_step,
               "run on the simulated clock, one step per client request (raven_twin/step)");
  bool no_arm_swap = false;
  app.add_flag("--no-arm-swap", no_arm_swap,
               "publish each arm on its own measured_js (upstream swaps them: arm1 = green)");
  app.add_option("--command-wait", server.command_wait,
                 "lock-step: wall seconds a step waits for the commands it names before it is "
                 "refused")
      ->check(CLI::PositiveNumber);
  bridge::ros1::CrtkFaceOptions crtk;
  app.add_option("--crtk-namespace", crtk.ros_namespace,
                 "namespace of the standard CRTK face, relative to the node's (absolute with a "
                 "leading /)")
      ->capture_default_str();
  std::vector<std::string> crtk_arms{crtk.arm_names.begin(), crtk.arm_names.end()};
  app.add_option("--crtk-arms", crtk_arms,
                 "the standard CRTK face's names of the gold (left) and green (right) arm, e.g. "
                 "PSM1 PSM2")
      ->expected(2)
      ->capture_default_str();
  bool no_crtk = false;
  app.add_flag("--no-crtk", no_crtk, "serve the robot's own topics only, no standard CRTK face");
  double duration = 0.0;
  app.add_option("--duration", duration,
                 "stop after this much platform time (s); 0: run until "
                 "interrupted")
      ->check(CLI::NonNegativeNumber);
  CLI11_PARSE(app, argc, argv);

  try {
    twin.launch_file = launch;
    twin.clock = server.lock_step ? bridge::ClockKind::Simulated : bridge::ClockKind::Wall;
    if (ambf_model) twin.bindings = twin::ArmBindings::ambfRaven();
    if (soft_body_sleep) {
      twin.adjust_scene = [](ambf_like::SceneSpec& scene) {
        scene.world.soft_body_sleep.enabled = true;
      };
    }
    // The motor model is the cable-driven robot's: in its joint convention, on our model.
    if (actuation == common::ActuationKind::Motors && !ambf_model && twin.profile == "physical") {
      (calibration.empty() ? twin::CalibrationProfile::shipped()
                           : twin::CalibrationProfile::load(calibration))
          .applyTo(twin);
    }
    server.arm_swap = !no_arm_swap;
    twin::TwinPlatform platform(twin);
    if (!no_crtk) {
      std::copy(crtk_arms.begin(), crtk_arms.end(), crtk.arm_names.begin());
      crtk.profile = platform.core().profile();
      server.crtk = crtk;
    }
    // The scene's bodies, sensors and actuators on AMBF's topics, served after every cycle.
    twin::ros1::AmbfObjectTopics objects(platform.world(), server.lock_step);
    server.after_cycle = [&] { objects.update(platform.now()); };
    bridge::ros1::RavenRosServer ros_server(platform, "", server);
    const bridge::ros1::MasterWatch master_watch;  // registers again with a restarted master
    spdlog::info("raven_twin: {} on {} ({}, {} clock, arm swap {}, standard CRTK {})",
                 twin.motors ? "the twin (motor-level actuation)" : "the twin (ideal servos)",
                 bridge::ros1::masterUri(), twin.profile,
                 server.lock_step ? "lock-step simulated" : "wall", server.arm_swap ? "on" : "off",
                 no_crtk ? "off"
                         : "under " + crtk.ros_namespace + "/{" + crtk.arm_names[0] + "," +
                               crtk.arm_names[1] + "}");
    ros_server.spin(duration);
  } catch (const std::exception& e) {
    spdlog::error("{}", e.what());
    return 1;
  }
  return 0;
}
