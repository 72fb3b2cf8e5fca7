#include "bridge/ros/ros_conversions.hpp"

#include <algorithm>
#include <cmath>

#include "common/printable.hpp"

namespace bridge::ros1 {

namespace {

using raven::kJointCount;

std::string valueError(const std::string& field, std::size_t index, double value) {
  return field + "[" + std::to_string(index) + "] is " + std::to_string(value) +
         ": values must be finite";
}

/// Copies a scalar, or a fixed-size array of the same length (the message's boost::array, the
/// snapshot's std::array).
template <typename Dst, typename Src>
void assign(Dst& dst, const Src& src) {
  dst = src;
}
template <typename T, typename U, std::size_t N>
void assign(boost::array<T, N>& dst, const std::array<U, N>& src) {
  std::copy(src.begin(), src.end(), dst.begin());
}
template <typename T, typename U, std::size_t N>
void assign(std::array<T, N>& dst, const boost::array<U, N>& src) {
  std::copy(src.begin(), src.end(), dst.begin());
}

/// Calls `f(message field, snapshot field)` for every raven_state field but the stamp and dt:
/// the one list of how the message and the snapshot correspond, used in both directions.
template <typename Message, typename Snapshot, typename F>
void pairFields(Message& m, Snapshot& s, F f) {
  f(m.runlevel, s.runlevel);
  f(m.sublevel, s.sublevel);
  f(m.last_seq, s.last_seq);
  f(m.type, s.type);
  f(m.pos, s.pos);
  f(m.ori, s.ori);
  f(m.ori_d, s.ori_d);
  f(m.pos_d, s.pos_d);
  f(m.encVals, s.enc_vals);
  f(m.dac_val, s.dac_val);
  f(m.tau, s.tau);
  f(m.mpos, s.mpos);
  f(m.jpos, s.jpos);
  f(m.mvel, s.mvel);
  f(m.jvel, s.jvel);
  f(m.mpos_d, s.mpos_d);
  f(m.jpos_d, s.jpos_d);
  f(m.grasp_d, s.grasp_d);
  f(m.encoffsets, s.encoffsets);
  f(m.jac_vel, s.jac_vel);
  f(m.jac_f, s.jac_f);
}

}  // namespace

Parsed<ArmJoints> armJointsFromValues(const std::vector<double>& p, const std::string& field) {
  if (p.size() != 7 && p.size() != 15) {
    return Parsed<ArmJoints>::fail(field + " has " + std::to_string(p.size()) +
                                   " values; expected 7 (shoulder, elbow, insertion, roll, "
                                   "wrist, jaw1, jaw2) or 15 (those 7, then 8 zeros)");
  }
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (!std::isfinite(p[i])) return Parsed<ArmJoints>::fail(valueError(field, i, p[i]));
    if (i >= 7 && p[i] != 0.0) {
      return Parsed<ArmJoints>::fail(field + "[" + std::to_string(i) +
                                     "] is not 0: values 7..14 of a 15-value command are unused "
                                     "and must be 0");
    }
  }
  return Parsed<ArmJoints>::ok(Eigen::Map<const ArmJoints>(p.data()));
}

Parsed<ArmJoints> armJointsFromCommand(const sensor_msgs::JointState& message) {
  return armJointsFromValues(message.position, "position");
}

Parsed<StateCommand> stateCommandFrom(const crtk_msgs::StringStamped& message) {
  if (auto command = parseStateCommand(message.string)) return Parsed<StateCommand>::ok(*command);
  constexpr std::size_t kLongestEcho = 40;
  return Parsed<StateCommand>::fail("unknown state command '" +
                                    common::printable(message.string, kLongestEcho) +
                                    "' (expected enable, disable, pause, resume, home or unhome)");
}

Parsed<double> graspFromCommand(const sensor_msgs::JointState& message) {
  if (message.position.empty()) {
    return Parsed<double>::fail("position is empty; expected the grasper value in position[0]");
  }
  if (!std::isfinite(message.position[0])) {
    return Parsed<double>::fail(valueError("position", 0, message.position[0]));
  }
  return Parsed<double>::ok(message.position[0]);
}

namespace {

/// A rigid transform from a message's translation and quaternion, checked.
Parsed<Eigen::Isometry3d> checkedPose(const Eigen::Vector3d& translation, Eigen::Quaterniond q,
                                      bool zero_is_identity) {
  if (!translation.allFinite() || !q.coeffs().allFinite()) {
    return Parsed<Eigen::Isometry3d>::fail("the pose holds NaN or infinite values");
  }
  if (zero_is_identity && q.coeffs().isZero(0.0)) q = Eigen::Quaterniond::Identity();
  if (std::abs(q.norm() - 1.0) > 1e-3) {
    return Parsed<Eigen::Isometry3d>::fail("the rotation quaternion has length " +
                                           std::to_string(q.norm()) + ", not 1");
  }
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = q.normalized().toRotationMatrix();
  pose.translation() = translation;
  return Parsed<Eigen::Isometry3d>::ok(pose);
}

}  // namespace

Parsed<Eigen::Isometry3d> poseFromTransform(const geometry_msgs::Transform& message,
                                            bool zero_is_identity) {
  const auto& t = message.translation;
  const auto& r = message.rotation;
  return checkedPose({t.x, t.y, t.z}, {r.w, r.x, r.y, r.z}, zero_is_identity);
}

Parsed<Eigen::Isometry3d> poseFromPose(const geometry_msgs::Pose& message) {
  const auto& t = message.position;
  const auto& r = message.orientation;
  return checkedPose({t.x, t.y, t.z}, {r.w, r.x, r.y, r.z}, false);
}

sensor_msgs::JointState toJointState(const JointSample& sample, std::string_view colour,
                                     ::ros::Time stamp) {
  sensor_msgs::JointState m;
  m.header.stamp = stamp;
  static constexpr std::array<const char*, kJointCount> kSuffix{"shoulder", "elbow", "ins", "roll",
                                                                "wrist",    "jaw1",  "jaw2"};
  for (const char* suffix : kSuffix) m.name.push_back(std::string(colour) + "_" + suffix);
  m.position.assign(sample.position.data(), sample.position.data() + kJointCount);
  m.velocity.assign(sample.velocity.data(), sample.velocity.data() + kJointCount);
  m.effort.assign(sample.effort.data(), sample.effort.data() + kJointCount);
  return m;
}

Parsed<JointSample> jointSampleFromState(const sensor_msgs::JointState& message) {
  auto sized = [](const std::vector<double>& v, bool optional) {
    return v.size() == kJointCount || (optional && v.empty());
  };
  if (!sized(message.position, false) || !sized(message.velocity, true) ||
      !sized(message.effort, true)) {
    return Parsed<JointSample>::fail(
        "expected 7 positions (and 7 or no velocities and efforts), got " +
        std::to_string(message.position.size()) + ", " + std::to_string(message.velocity.size()) +
        ", " + std::to_string(message.effort.size()));
  }
  JointSample s;
  s.time = message.header.stamp.toSec();
  s.position = Eigen::Map<const ArmJoints>(message.position.data());
  if (!message.velocity.empty()) s.velocity = Eigen::Map<const ArmJoints>(message.velocity.data());
  if (!message.effort.empty()) s.effort = Eigen::Map<const ArmJoints>(message.effort.data());
  if (!s.position.allFinite()) return Parsed<JointSample>::fail("a position is not finite");
  return Parsed<JointSample>::ok(s);
}

sensor_msgs::JointState toGraspState(const JointSample& sample, std::string_view colour,
                                     ::ros::Time stamp) {
  sensor_msgs::JointState m;
  m.header.stamp = stamp;
  const std::string c(colour);
  m.name = {c + "_grasp", c + "_jaw1", c + "_jaw2"};
  const double j1 = sample.position(raven::kJaw1), j2 = sample.position(raven::kJaw2);
  m.position = {j1 + j2, j1, j2};
  const double v1 = sample.velocity(raven::kJaw1), v2 = sample.velocity(raven::kJaw2);
  m.velocity = {v1 + v2, v1, v2};
  return m;
}

sensor_msgs::JointState toJawState(const JointSample& sample, ::ros::Time stamp) {
  sensor_msgs::JointState m;
  m.header.stamp = stamp;
  m.name = {"jaw"};
  m.position = {sample.position(raven::kJaw1) + sample.position(raven::kJaw2)};
  m.velocity = {sample.velocity(raven::kJaw1) + sample.velocity(raven::kJaw2)};
  m.effort = {sample.effort(raven::kJaw1) + sample.effort(raven::kJaw2)};
  return m;
}

geometry_msgs::Pose toPose(const Eigen::Isometry3d& pose) {
  geometry_msgs::Pose m;
  m.position.x = pose.translation().x();
  m.position.y = pose.translation().y();
  m.position.z = pose.translation().z();
  const Eigen::Quaterniond q(pose.linear());
  m.orientation.w = q.w();
  m.orientation.x = q.x();
  m.orientation.y = q.y();
  m.orientation.z = q.z();
  return m;
}

geometry_msgs::PoseStamped toPoseStamped(const Eigen::Isometry3d& pose, ::ros::Time stamp,
                                         std::string frame) {
  geometry_msgs::PoseStamped m;
  m.header.stamp = stamp;
  m.header.frame_id = std::move(frame);
  m.pose = toPose(pose);
  return m;
}

geometry_msgs::TransformStamped toTransformStamped(const Eigen::Isometry3d& pose, ::ros::Time stamp,
                                                   std::string frame, std::string child_frame) {
  const geometry_msgs::Pose p = toPose(pose);
  geometry_msgs::TransformStamped m;
  m.header.stamp = stamp;
  m.header.frame_id = std::move(frame);
  m.child_frame_id = std::move(child_frame);
  m.transform.translation.x = p.position.x;
  m.transform.translation.y = p.position.y;
  m.transform.translation.z = p.position.z;
  m.transform.rotation = p.orientation;
  return m;
}

namespace {

geometry_msgs::Vector3 toVector3(const Eigen::Vector3d& v) {
  geometry_msgs::Vector3 m;
  m.x = v.x();
  m.y = v.y();
  m.z = v.z();
  return m;
}

}  // namespace

geometry_msgs::TwistStamped toTwistStamped(const Eigen::Matrix<double, 6, 1>& twist,
                                           ::ros::Time stamp, std::string frame) {
  geometry_msgs::TwistStamped m;
  m.header.stamp = stamp;
  m.header.frame_id = std::move(frame);
  m.twist.linear = toVector3(twist.head<3>());
  m.twist.angular = toVector3(twist.tail<3>());
  return m;
}

geometry_msgs::WrenchStamped toWrenchStamped(const GrasperForces& forces, ::ros::Time stamp,
                                             std::string frame) {
  geometry_msgs::WrenchStamped m;
  m.header.stamp = stamp;
  m.header.frame_id = std::move(frame);
  m.wrench.force = toVector3(forces.force);
  m.wrench.torque = toVector3(forces.torque);
  return m;
}

raven_twin::GraspForces toGraspForces(const GrasperForces& forces, ::ros::Time stamp,
                                      std::string frame) {
  raven_twin::GraspForces m;
  m.header.stamp = stamp;
  m.header.frame_id = std::move(frame);
  for (std::size_t j = 0; j < 2; ++j) {
    m.normal[j] = toVector3(forces.jaws[j].normal);
    m.friction[j] = toVector3(forces.jaws[j].friction);
    m.contacts[j] = static_cast<std::uint32_t>(forces.jaws[j].contacts);
  }
  return m;
}

Parsed<GrasperForces> grasperForcesFrom(const raven_twin::GraspForces& jaws,
                                        const geometry_msgs::Wrench& wrench) {
  auto vector = [](const geometry_msgs::Vector3& v) { return Eigen::Vector3d(v.x, v.y, v.z); };
  GrasperForces out;
  for (std::size_t j = 0; j < 2; ++j) {
    out.jaws[j].normal = vector(jaws.normal[j]);
    out.jaws[j].friction = vector(jaws.friction[j]);
    out.jaws[j].contacts = static_cast<int>(jaws.contacts[j]);
    if (!out.jaws[j].normal.allFinite() || !out.jaws[j].friction.allFinite()) {
      return {std::nullopt, "jaw_forces: jaw " + std::to_string(j + 1) + " is not finite"};
    }
  }
  out.force = vector(wrench.force);
  out.torque = vector(wrench.torque);
  if (!out.force.allFinite() || !out.torque.allFinite()) {
    return {std::nullopt, "measured_cf: the wrench is not finite"};
  }
  return {out, {}};
}

Parsed<OperatingStatus> operatingStatusFrom(const crtk_msgs::operating_state& message) {
  const auto state = parseOperatingState(message.state);
  if (!state) {
    return Parsed<OperatingStatus>::fail("unknown operating state '" + message.state + "'");
  }
  return Parsed<OperatingStatus>::ok({*state, message.is_homed != 0, message.is_busy != 0});
}

raven_2::raven_state toRavenState(const RavenStateSnapshot& s, ::ros::Time stamp) {
  raven_2::raven_state m;
  m.hdr.stamp = stamp;
  m.dt = ::ros::Duration(s.dt);
  pairFields(m, s, [](auto& to, const auto& from) { assign(to, from); });
  return m;
}

RavenStateSnapshot ravenStateFrom(const raven_2::raven_state& m) {
  RavenStateSnapshot s;
  s.time = m.hdr.stamp.toSec();
  s.dt = m.dt.toSec();
  pairFields(m, s, [](const auto& from, auto& to) { assign(to, from); });
  return s;
}

}  // namespace bridge::ros1
