#include "arm_design.hpp"

#include <cmath>
#include <stdexcept>

#include "raven/design/firmware_links.hpp"

namespace raven::model {

namespace {

using Eigen::AngleAxisd;
using Eigen::Isometry3d;
using Eigen::Vector3d;

/// Capsules along the great-circle arc of radius `radius` from direction `from` to `to`.
std::vector<Primitive> arc(const Vector3d& from, const Vector3d& to, double radius,
                           double thickness, int pieces) {
  std::vector<Primitive> out;
  const Vector3d axis = from.cross(to).normalized();
  const double angle = std::acos(std::clamp(from.normalized().dot(to.normalized()), -1.0, 1.0));
  auto at = [&](int k) {
    return Vector3d(AngleAxisd(angle * k / pieces, axis) * from.normalized() * radius);
  };
  for (int k = 1; k <= pieces; ++k) out.push_back(capsuleBetween(at(k - 1), at(k), thickness));
  return out;
}

/// The robot's frame 0 of `arm` in {B}: the controller chain's base before its Rz(+25 deg left,
/// -25 deg right) (raven2-kinematics.md §B), where the firmware's gravity is -x (§3 of
/// raven2-actuation.md).
Isometry3d firmwareFrame0(const ArmConvention& c, Arm arm) {
  const double rz = (arm == Arm::Left ? 25.0 : -25.0) * M_PI / 180.0;
  return c.base * AngleAxisd(-rz, Vector3d::UnitZ());
}

/// Gives links 1, 2 and the carriage the robot's own masses and centres (FirmwareLinks). Link 3's
/// mass, which the firmware puts at frame 3's origin (the carriage's), is the carriage's and the
/// instrument's together: the carriage takes what the instrument leaves, at its own origin. (Put
/// where the firmware's lumped centre would be, 17 cm off the light carriage, it made the
/// constraint formulation's jaws diverge.) The instrument's weight hangs along its shaft.
void weighAsTheRobot(const PlatformProfile& profile, Arm arm, const ArmJoints& home,
                     BodyDraft& link1, BodyDraft& link2, BodyDraft& carriage,
                     const std::vector<const BodyDraft*>& instrument) {
  if (!profile.firmware_kinematics) {
    throw std::invalid_argument(
        "profile '" + profile.name +
        "' has no firmware_kinematics: the links' weights are in its frames");
  }
  const auto& firmware_chain = (*profile.firmware_kinematics)[raven::slot(arm)];
  const auto firmware = ArmKinematics(firmware_chain, profile.limits).frames(home);
  const Isometry3d frame0 = firmwareFrame0(ArmKinematics::of(profile, arm).convention(), arm);
  const auto links = design::FirmwareLinks::of(arm);
  for (auto [k, body] : {std::pair{0, &link1}, std::pair{1, &link2}}) {
    const auto i = static_cast<std::size_t>(k);
    body->mass = links.mass[i];
    body->centre_of_mass = body->pose.inverse() * frame0 * firmware[i] * links.centre[i];
  }
  double rest = links.mass[2];
  for (const BodyDraft* b : instrument) rest -= b->mass;
  if (rest <= 0.0) throw std::invalid_argument("the instrument outweighs the robot's link 3");
  carriage.mass = rest;
  carriage.centre_of_mass = Vector3d::Zero();
}

Primitive box(const Vector3d& size, const Vector3d& centre) {
  Primitive p;
  p.type = Primitive::Type::Box;
  p.size = size;
  p.pose.translation() = centre;
  return p;
}

}  // namespace

ModelDraft designArm(const PlatformProfile& profile, Arm arm, const ArmDesign& d) {
  const auto kin = ArmKinematics::of(profile, arm);
  const auto& c = kin.convention();
  const ArmJoints& home = profile.home;
  const auto f = kin.frames(home);
  const double side = c.grasp_scale > 0 ? 1.0 : -1.0;
  const std::string name(armName(arm));

  ModelDraft m;
  m.name_space = "/raven2/" + name + "/";
  m.label = name;
  m.comment = "Raven-II " + name + " arm, generated from the '" + profile.name +
              "' profile by raven_description/tools (do not edit by hand)";
  m.ignore_inter_collision = true;  // links of one arm never touch; the other arm's do

  // The mount is the frame before the shoulder's rotation: base * Rx(alpha0).
  BodyDraft mount{.name = "mount",
                  .pose = c.base * Isometry3d(AngleAxisd(c.alpha[0], Vector3d::UnitX()))};
  mount.primitives.push_back(box({0.09, 0.09, 0.08}, {0, 0, d.link1_radius + 0.04}));

  // Links 1 and 2 are arcs around the remote centre (the origin of their frames).
  const Vector3d elbow_axis = AngleAxisd(c.alpha[1], Vector3d::UnitX()) * Vector3d::UnitZ();
  BodyDraft link1{.name = "link1", .pose = f[0]};
  link1.primitives = arc(Vector3d::UnitZ(), elbow_axis, d.link1_radius, d.link_radius, 3);

  const Vector3d insertion_axis = AngleAxisd(c.alpha[2], Vector3d::UnitX()) * Vector3d::UnitZ();
  BodyDraft link2{.name = "link2", .pose = f[1]};
  link2.primitives = arc(Vector3d::UnitZ(), insertion_axis, d.link2_radius, d.link_radius, 4);
  link2.primitives.push_back(capsuleBetween(d.link1_radius * Vector3d::UnitZ(),
                                            d.link2_radius * Vector3d::UnitZ(), d.link_radius));
  link2.primitives.push_back(capsuleBetween(d.rail_near * insertion_axis,
                                            d.rail_far * insertion_axis, 0.6 * d.link_radius));

  BodyDraft carriage{.name = "carriage", .pose = f[2]};
  carriage.primitives.push_back(box(d.carriage_size, Vector3d::Zero()));

  // The instrument: its frame is at the wrist point, the shaft runs up to the carriage.
  BodyDraft shaft{
      .name = "shaft", .pose = f[3], .mass = d.shaft_mass, .armature = d.shaft_armature};
  shaft.primitives.push_back(
      cylinderBetween(Vector3d(0, 0, 0.004), Vector3d(0, 0, -c.d4), d.shaft_radius));

  BodyDraft wrist{
      .name = "wrist_link", .pose = f[4], .mass = d.wrist_mass, .armature = d.wrist_armature};
  const Vector3d jaw_axis_point(c.tool_length, 0, 0);  // in the wrist frame (after Rx(alpha5))
  wrist.primitives.push_back(
      capsuleBetween(Vector3d::Zero(), 0.75 * jaw_axis_point, d.wrist_radius));

  // The jaws turn about the jaw axis (the z axis after Rx(alpha5) Tx(Lw)): jaw 1 by
  // +side * jaw1, jaw 2 by -side * jaw2, so their mean direction is the DH theta6 / 2.
  const Isometry3d jaw_pivot =
      f[4] * AngleAxisd(c.alpha[5], Vector3d::UnitX()) * Eigen::Translation3d(jaw_axis_point);
  BodyDraft jaw1{.name = "jaw1_link",
                 .pose = jaw_pivot * AngleAxisd(side * home(kJaw1), Vector3d::UnitZ()),
                 .mass = d.jaw_mass,
                 .armature = d.jaw_armature,
                 .hull = jawHullPoints(d.jaw_length, d.jaw_width, d.jaw_thickness, int(side)),
                 .hull_mesh = "jaw1_" + name + ".obj",
                 .friction = d.jaw_friction};
  BodyDraft jaw2{.name = "jaw2_link",
                 .pose = jaw_pivot * AngleAxisd(-side * home(kJaw2), Vector3d::UnitZ()),
                 .mass = d.jaw_mass,
                 .armature = d.jaw_armature,
                 .hull = jawHullPoints(d.jaw_length, d.jaw_width, d.jaw_thickness, -int(side)),
                 .hull_mesh = "jaw2_" + name + ".obj",
                 .friction = d.jaw_friction};

  weighAsTheRobot(profile, arm, home, link1, link2, carriage, {&shaft, &wrist, &jaw1, &jaw2});

  const Vector3d z = Vector3d::UnitZ();
  auto joint = [&](const char* joint_name, const BodyDraft& parent, const BodyDraft& child,
                   const Vector3d& axis, const Vector3d& pivot, int index, bool prismatic) {
    auto j = connect(joint_name, parent, child, axis, pivot, home(index), prismatic);
    j.low = profile.limits.low(index);
    j.high = profile.limits.high(index);
    j.max_effort = d.max_effort[static_cast<std::size_t>(std::min(index, 5))];
    j.max_velocity = d.max_velocity[static_cast<std::size_t>(std::min(index, 5))];
    m.joints.push_back(j);
  };
  joint("shoulder", mount, link1, z, Vector3d::Zero(), kShoulder, false);
  joint("elbow", link1, link2, z, Vector3d::Zero(), kElbow, false);
  joint("insertion", link2, carriage, z, Vector3d::Zero(), kInsertion, true);
  joint("roll", carriage, shaft, z, Vector3d(0, 0, -c.d4), kRoll, false);
  joint("wrist", shaft, wrist, z, Vector3d::Zero(), kWrist, false);
  joint("jaw1", wrist, jaw1, side * z, Vector3d::Zero(), kJaw1, false);
  joint("jaw2", wrist, jaw2, -side * z, Vector3d::Zero(), kJaw2, false);

  m.bodies = {mount, link1, link2, carriage, shaft, wrist, jaw1, jaw2};
  return m;
}

}  // namespace raven::model
