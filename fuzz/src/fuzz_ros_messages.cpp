// Fuzz target: the messages a Raven-II's ROS interface takes in, built field by field from the
// input (any length, any double bit pattern: NaN, inf, 1e308), checked as the twin node checks
// them and sent to the robot's command layer, which then runs cycles. Whatever arrives, every
// setpoint stays finite and within the joint limits (the safety limits hold on every path).
// Camera images (colour or depth, any encoding, sizes, step and data) a policy takes in are read
// or refused, and a frame read has exactly its width x height pixels.

#include <fuzzer/FuzzedDataProvider.h>
#include <geometry_msgs/Transform.h>
#include <geometry_msgs/Wrench.h>
#include <raven_2/raven_state.h>
#include <raven_twin/GraspForces.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/JointState.h>

#include <cstdint>
#include <cstring>

#include "bridge/operating_state.hpp"
#include "bridge/ros/image_conversions.hpp"
#include "bridge/ros/ros_conversions.hpp"
#include "fuzz_file.hpp"
#include "raven/platform_profile.hpp"
#include "twin/raven_core.hpp"

namespace {

using bridge::Arm;
namespace r1 = bridge::ros1;

double anyDouble(FuzzedDataProvider& in) {
  const auto bits = in.ConsumeIntegral<std::uint64_t>();
  double value;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

std::vector<double> anyDoubles(FuzzedDataProvider& in) {
  std::vector<double> values(in.ConsumeIntegralInRange<std::size_t>(0, 20));
  for (auto& v : values) v = in.ConsumeBool() ? anyDouble(in) : in.ConsumeFloatingPoint<double>();
  return values;
}

sensor_msgs::JointState anyJointState(FuzzedDataProvider& in) {
  sensor_msgs::JointState m;
  m.name.resize(in.ConsumeIntegralInRange<std::size_t>(0, 16));
  for (auto& n : m.name) n = in.ConsumeRandomLengthString(24);
  m.position = anyDoubles(in);
  m.velocity = anyDoubles(in);
  m.effort = anyDoubles(in);
  return m;
}

geometry_msgs::Transform anyTransform(FuzzedDataProvider& in) {
  geometry_msgs::Transform m;
  m.translation.x = anyDouble(in);
  m.translation.y = anyDouble(in);
  m.translation.z = anyDouble(in);
  m.rotation.x = anyDouble(in);
  m.rotation.y = anyDouble(in);
  m.rotation.z = anyDouble(in);
  m.rotation.w = anyDouble(in);
  return m;
}

/// An image message of any encoding a camera may send (or another), sizes and data.
sensor_msgs::Image anyImage(FuzzedDataProvider& in) {
  static const char* const kEncodings[] = {"rgb8",  "bgr8",  "rgba8", "bgra8",   "mono8",
                                           "32FC1", "16UC1", "bgr16", "nonsense"};
  sensor_msgs::Image m;
  m.encoding = kEncodings[in.ConsumeIntegralInRange<std::size_t>(0, 8)];
  m.width = in.ConsumeIntegralInRange<std::uint32_t>(0, 40);
  m.height = in.ConsumeIntegralInRange<std::uint32_t>(0, 40);
  m.step = in.ConsumeBool() ? in.ConsumeIntegral<std::uint32_t>()
                            : in.ConsumeIntegralInRange<std::uint32_t>(0, 200);
  m.is_bigendian = in.ConsumeIntegral<std::uint8_t>();
  m.data = in.ConsumeBytes<std::uint8_t>(in.ConsumeIntegralInRange<std::size_t>(0, 8000));
  return m;
}

void checkImage(const sensor_msgs::Image& message) {
  const auto frame = r1::frameFromImage(message);
  if (!frame.value) return;
  const auto pixels = static_cast<std::size_t>(frame.value->width) * frame.value->height;
  const bool whole = frame.value->isDepth() ? frame.value->depth.size() == pixels
                                            : frame.value->rgb.size() == 3 * pixels;
  if (pixels == 0 || !whole) fuzz::fail("an image frame that is not width x height pixels");
}

/// An enabled, homed command layer of the physical robot, made once and copied per input.
const twin::RavenCore& readyCore() {
  static const twin::RavenCore ready = [] {
    const auto profile = raven::builtinProfile("physical");
    twin::RavenCore core(profile, bridge::ServoLimits{}, {profile.home, profile.home});
    core.apply(bridge::StateCommand::Enable);
    core.apply(bridge::StateCommand::Home);
    for (int i = 0; i < 30000 && core.status().is_busy; ++i) {
      core.cycle({core.setpoint(Arm::Left), core.setpoint(Arm::Right)});
    }
    return core;
  }();
  return ready;
}

void checkSetpoints(const twin::RavenCore& core, const raven::JointLimits& limits) {
  for (Arm arm : raven::kArms) {
    const auto& q = core.setpoint(arm);
    if (!q.allFinite()) fuzz::fail("a non-finite setpoint");
    if ((q.array() < limits.low.array() - 1e-9).any() ||
        (q.array() > limits.high.array() + 1e-9).any()) {
      fuzz::fail("a setpoint outside the joint limits");
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider in(data, size);
  static const raven::JointLimits limits = raven::builtinProfile("physical").limits;
  twin::RavenCore core = readyCore();
  while (in.remaining_bytes() > 0) {
    const Arm arm = in.ConsumeBool() ? Arm::Left : Arm::Right;
    switch (in.ConsumeIntegralInRange<int>(0, 8)) {
      case 0: {
        const auto q = r1::armJointsFromCommand(anyJointState(in));
        if (!q.value) break;
        switch (in.ConsumeIntegralInRange<int>(0, 2)) {
          case 0:
            core.apply(bridge::ServoJp{arm, *q.value});
            break;
          case 1:
            core.apply(bridge::ServoJr{arm, *q.value});
            break;
          default:
            core.apply(bridge::MoveJp{arm, *q.value});
            break;
        }
        break;
      }
      case 1: {
        const auto jaw = r1::graspFromCommand(anyJointState(in));
        if (!jaw.value) break;
        if (in.ConsumeBool()) {
          core.apply(bridge::ServoJawJp{arm, *jaw.value});
        } else {
          core.apply(bridge::ServoJawJr{arm, *jaw.value});
        }
        break;
      }
      case 2: {
        const bool increment = in.ConsumeBool();
        const auto pose = r1::poseFromTransform(anyTransform(in), increment);
        if (!pose.value) break;
        if (increment) {
          core.apply(bridge::ServoCr{arm, *pose.value});
        } else {
          core.apply(bridge::ServoCp{arm, *pose.value});
        }
        break;
      }
      case 3:
        if (const auto command = bridge::parseStateCommand(in.ConsumeRandomLengthString(16))) {
          core.apply(*command);
        }
        break;
      case 4:
        for (int c = in.ConsumeIntegralInRange<int>(1, 50); c > 0; --c) {
          core.cycle({core.setpoint(Arm::Left), core.setpoint(Arm::Right)});
          checkSetpoints(core, limits);
        }
        break;
      case 5: {
        raven_2::raven_state m;
        for (auto& v : m.jpos) v = static_cast<float>(anyDouble(in));
        for (auto& v : m.pos) v = in.ConsumeIntegral<std::int32_t>();
        (void)r1::ravenStateFrom(m);
        break;
      }
      case 6:
        (void)r1::jointSampleFromState(anyJointState(in));
        break;
      case 7:
        checkImage(anyImage(in));
        break;
      default: {
        raven_twin::GraspForces jaws;
        for (auto& f : jaws.normal) f.x = anyDouble(in);
        for (auto& f : jaws.friction) f.z = anyDouble(in);
        geometry_msgs::Wrench wrench;
        wrench.force.x = anyDouble(in);
        wrench.torque.y = anyDouble(in);
        (void)r1::grasperForcesFrom(jaws, wrench);
        break;
      }
    }
  }
  checkSetpoints(core, limits);
  return 0;
}
