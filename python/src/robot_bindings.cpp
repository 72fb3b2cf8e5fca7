// A Raven-II over ROS for Python, as a policy meets it (scenario::PegTransferRobot): the
// physical robot or a twin node in another process, through the same client, controller, caps
// and limits as the gamepad path; the rings from their pose topics when there are any; the
// cameras from their image topics. Waits release the GIL.

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <unistd.h>

#include <optional>

#include "bindings.hpp"
#include "bridge/ros/raven_ros_client.hpp"
#include "bridge/ros/ros_camera_images.hpp"
#include "bridge/ros/ros_runtime.hpp"
#include "bridge/ros/ros_scene_perception.hpp"
#include "scenario/peg_transfer_robot.hpp"

namespace py = pybind11;

namespace raven_python {

namespace {

/// ROS once per process, under a name of its own (several policies may share a master).
void initRosOnce() {
  static const bool started = [] {
    int argc = 0;
    bridge::ros1::initRos(argc, nullptr, "raven_policy_" + std::to_string(::getpid()),
                          /*ros_handles_sigint=*/false);
    return true;
  }();
  (void)started;
}

/// The robot, what sees its rings and its cameras, owned together.
class RobotOverRos {
 public:
  RobotOverRos(const std::string& robot_namespace, bool arm_swap,
               const std::optional<std::string>& scene_namespace,
               const std::vector<std::string>& camera_topics, double connect_timeout) {
    initRosOnce();
    bridge::ros1::RosClientOptions client;
    client.robot_namespace = robot_namespace;
    client.arm_swap = arm_swap;
    client.connect_timeout = connect_timeout;
    client_.emplace(client);
    if (scene_namespace) {
      bridge::ros1::RosPerceptionOptions seeing;
      seeing.topic_namespace = *scene_namespace;
      seeing.timeout = connect_timeout;
      for (const scenario::RingJob& job : scenario::PegLayout{}.jobs) {
        seeing.objects.push_back(job.ring);
      }
      scene_.emplace(seeing);
    }
    if (!camera_topics.empty())
      cameras_.emplace(bridge::ros1::RosCameraOptions{camera_topics, connect_timeout});
    robot_.emplace(*client_, scene_ ? &*scene_ : nullptr);
  }

  scenario::PegTransferRobot& robot() { return *robot_; }

  std::vector<std::uint64_t> received() const {
    std::vector<std::uint64_t> counts;
    for (std::size_t i = 0; cameras_ && i < cameras_->topics().size(); ++i) {
      counts.push_back(cameras_->received(i));
    }
    return counts;
  }

  std::vector<bridge::CameraFrame> images(const std::vector<std::uint64_t>& after) const {
    if (!cameras_) throw std::logic_error("no camera topics were given");
    if (after.size() != cameras_->topics().size()) {
      throw std::invalid_argument("one count per camera topic");
    }
    std::vector<bridge::CameraFrame> frames;
    for (std::size_t i = 0; i < after.size(); ++i) frames.push_back(cameras_->latest(i, after[i]));
    return frames;
  }

 private:
  std::optional<bridge::ros1::RavenRosClient> client_;
  std::optional<bridge::ros1::RosScenePerception> scene_;
  std::optional<bridge::ros1::RosCameraImages> cameras_;
  std::optional<scenario::PegTransferRobot> robot_;
};

/// A colour frame as (H, W, 3) uint8, a depth frame as (H, W) float32 (m).
py::array imageArray(const bridge::CameraFrame& frame) {
  if (frame.isDepth()) {
    py::array_t<float> out({frame.height, frame.width});
    std::copy(frame.depth.begin(), frame.depth.end(), out.mutable_data());
    return out;
  }
  py::array_t<std::uint8_t> out({frame.height, frame.width, 3});
  std::copy(frame.rgb.begin(), frame.rgb.end(), out.mutable_data());
  return out;
}

}  // namespace

void bindRobotOverRos(py::module_& m) {
  py::class_<RobotOverRos>(m, "RobotOverRos",
                           "a Raven-II over its ROS 1 topics (the physical robot or a twin node "
                           "on the wall clock), as a peg-transfer policy meets it")
      .def(py::init([](const std::string& robot_namespace, bool arm_swap,
                       const std::optional<std::string>& scene_namespace,
                       const std::vector<std::string>& camera_topics, double connect_timeout) {
             py::gil_scoped_release release;
             return std::make_unique<RobotOverRos>(robot_namespace, arm_swap, scene_namespace,
                                                   camera_topics, connect_timeout);
           }),
           py::arg("robot_namespace") = "", py::arg("arm_swap") = true,
           py::arg("scene_namespace") = py::none(),
           py::arg("camera_topics") = std::vector<std::string>{}, py::arg("connect_timeout") = 10.0,
           "ROS_MASTER_URI names the master. scene_namespace: the rings' AMBF object topics "
           "('/peg_transfer/' on the twin node), or None; camera_topics: sensor_msgs/Image "
           "topics (colour or depth). Throws naming what is not found within connect_timeout s")
      .def(
          "make_ready",
          [](RobotOverRos& r, double timeout) {
            py::gil_scoped_release release;
            r.robot().makeReady(timeout);
          },
          py::arg("timeout") = 30.0, "enable and home the robot, the controller from there")
      .def(
          "observe", [](RobotOverRos& r) { return r.robot().observe(); },
          "the environment's 72-value state; the rings NaN without their topics")
      .def(
          "step",
          [](RobotOverRos& r, const Eigen::VectorXd& action) {
            scenario::RobotStep s;
            {
              py::gil_scoped_release release;
              s = r.robot().step(action);
            }
            return py::make_tuple(s.refused, s.faulted);
          },
          py::arg("action"),
          "one waypoint step of 14 joint deltas, as PegTransferEnv's: (refused, faulted)")
      .def(
          "placed", [](RobotOverRos& r) { return r.robot().placed(); },
          "rings on their target posts as their topics show, or None without them")
      .def("received", &RobotOverRos::received, "images taken in so far, per camera topic")
      .def(
          "images",
          [](const RobotOverRos& r, const std::vector<std::uint64_t>& after) {
            std::vector<bridge::CameraFrame> frames;
            {
              py::gil_scoped_release release;
              frames = r.images(after);
            }
            py::list out;
            for (const bridge::CameraFrame& f : frames) out.append(imageArray(f));
            return out;
          },
          py::arg("after"),
          "per camera topic its latest image once more than `after` (received()) came: colour "
          "(H, W, 3) uint8, depth (H, W) float32 in m (+inf: no reading)")
      .def_property_readonly("time", [](RobotOverRos& r) { return r.robot().time(); });
}

}  // namespace raven_python
