#include "arm_contacts.hpp"

#include <map>

#include "twin/calibration_profile.hpp"

namespace test_support {

double countInJoint(const twin::DriveTrain& drive, int joint) {
  return 1.0 / drive.countsPerMotorRadian() / drive.transmission(joint);
}

twin::TwinOptions frictionlessMotors() {
  twin::TwinOptions options;
  options.motors = twin::CalibrationProfile::shipped().mechanics;
  for (auto& m : *options.motors) {
    m.coulomb.setZero();
    m.load_friction.setZero();
    m.offset.setZero();
    m.face.setZero();
    m.face_compliance.setZero();
    m.cable_friction.setZero();
    m.cable_travel.setZero();
    m.gravity_error.setZero();
  }
  return options;
}

twin::TwinOptions withObstacle(const twin::TwinOptions& base,
                               const ambf_like::PrimitiveShape& shape,
                               const ambf_like::Transform& pose, double friction) {
  twin::TwinOptions options = base;
  options.adjust_scene = [shape, pose, friction](ambf_like::SceneSpec& scene) {
    for (auto& model : scene.models) {
      for (auto& body : model.bodies) body.surface.rolling_friction = 0.0;
    }
    ambf_like::ModelSpec obstacle;
    obstacle.name_space = "/test/";
    ambf_like::BodySpec body;
    body.name = "obstacle";
    body.surface.rolling_friction = 0.0;
    body.surface.static_friction = friction;
    body.collision.primitives.push_back(shape);
    body.collision.primitives.back().offset = ambf_like::Transform::Identity();
    body.location = pose;
    obstacle.bodies.push_back(body);
    scene.models.push_back(obstacle);
  };
  return options;
}

ArmChain chainOf(twin::TwinPlatform& twin, raven::Arm arm) {
  ambf_like::World& world = twin.world();
  ArmChain chain;
  const auto names = twin::ArmBindings::ourRaven().joints[raven::slot(arm)];
  std::map<std::string, std::string> parent_of;  // child body -> parent body (plain names)
  for (const auto& b : names) {
    const auto& spec = world.joint(b.name).spec();
    chain.joints.push_back(&world.joint(b.name));
    parent_of[spec.child] = spec.parent;
  }
  const std::string prefix = "/raven2/" + std::string(raven::armName(arm)) + "/";
  for (const auto* joint : chain.joints) {
    std::vector<std::string> moved;
    for (const auto& [body, parent] : parent_of) {
      // `body` moves with the joint when the joint's child is on its way to the base.
      for (std::string at = body;; at = parent_of.at(at)) {
        if (at == joint->spec().child) {
          moved.push_back(prefix + body);
          break;
        }
        if (!parent_of.contains(at)) break;
      }
    }
    chain.moves.push_back(moved);
  }
  return chain;
}

raven::ArmJoints contactLoads(twin::TwinPlatform& twin, raven::Arm arm) {
  ambf_like::World& world = twin.world();
  const ArmChain chain = chainOf(twin, arm);
  raven::ArmJoints loads = raven::ArmJoints::Zero();
  for (int j = 0; j < raven::kJointCount; ++j) {
    const auto& spec = chain.joints[static_cast<std::size_t>(j)]->spec();
    const ambf_like::Transform parent =
        world.body("/raven2/" + std::string(raven::armName(arm)) + "/" + spec.parent).pose();
    const Eigen::Vector3d axis = parent.linear() * spec.parent_axis.normalized();
    const Eigen::Vector3d pivot = parent * spec.parent_pivot;
    for (const auto& body : chain.moves[static_cast<std::size_t>(j)]) {
      for (const auto& c : world.contacts(body)) {
        const bool on_a = c.body_a == body;
        const Eigen::Vector3d impulse = c.normal_impulse * c.normal_on_b + c.friction_impulse;
        const Eigen::Vector3d force = (on_a ? 1.0 : -1.0) * impulse / world.stepSize();
        const Eigen::Vector3d at = c.position_on_b;
        loads(j) += spec.type == ambf_like::JointType::Prismatic
                        ? force.dot(axis)
                        : force.dot(axis.cross(at - pivot));
      }
    }
  }
  return loads;
}

bool touching(twin::TwinPlatform& twin, raven::Arm arm, int joint) {
  const ArmChain chain = chainOf(twin, arm);
  for (const auto& body : chain.moves[static_cast<std::size_t>(joint)]) {
    for (const auto& c : twin.world().contacts(body)) {
      if (c.normal_impulse > 0.0) return true;
    }
  }
  return false;
}

Eigen::Vector3d contactForceOn(const ambf_like::World& world, const std::string& name) {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  for (const auto& c : world.contacts(name)) {
    const Eigen::Vector3d impulse = c.normal_impulse * c.normal_on_b + c.friction_impulse;
    force += (c.body_a == name ? 1.0 : -1.0) * impulse / world.stepSize();
  }
  return force;
}

}  // namespace test_support
