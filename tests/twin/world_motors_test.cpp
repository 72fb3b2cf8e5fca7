// The motors drive the simulated links through the cables and carry what the links carry: the
// weight the calibration fitted, and what the tool presses on, checked against the statics.

#include <gtest/gtest.h>

#include <array>
#include <map>
#include <string>
#include <vector>

#include "bridge/raven_state.hpp"
#include "twin/calibration_profile.hpp"
#include "twin/gravity_compensation.hpp"
#include "twin/motor_controller.hpp"
#include "twin_fixtures.hpp"

namespace {

using raven::Arm;
using raven::ArmJoints;

/// The shipped mechanics without friction or gravity error: at rest the motors then carry the
/// links' weight alone.
twin::TwinOptions frictionlessMotors() {
  twin::TwinOptions options;
  options.motors = twin::CalibrationProfile::shipped().mechanics;
  for (auto& m : *options.motors) {
    m.coulomb.setZero();
    m.load_friction.setZero();
    m.gravity_error.setZero();
  }
  return options;
}

/// The torque the amplifiers apply (at the gearbox outputs): the logged DAC counts back in N m
/// (Tau itself may pass the DAC's clip).
ArmJoints appliedTorque(const twin::TwinPlatform& twin, Arm arm) {
  const auto state = twin.ravenState();
  const auto dac = twin::DacConversion::raven2(arm);
  ArmJoints applied;
  for (int i = 0; i < raven::kJointCount; ++i) {
    applied(i) = state->dac_val[static_cast<std::size_t>(bridge::ravenStateIndex(arm, i))] /
                 dac.counts_per_torque(i);
  }
  return applied;
}

ArmJoints loggedTau(const twin::TwinPlatform& twin, Arm arm) {
  const auto state = twin.ravenState();
  ArmJoints tau;
  for (int i = 0; i < raven::kJointCount; ++i) {
    tau(i) = state->tau[static_cast<std::size_t>(bridge::ravenStateIndex(arm, i))];
  }
  return tau;
}

/// The weight the calibration says `arm`'s motors carry at `joints` (at the gearbox outputs):
/// the firmware's gravity estimate times one plus the fitted gravity error.
ArmJoints fittedWeight(const twin::TwinOptions& options, Arm arm, const ArmJoints& joints) {
  const auto& m = (*options.motors)[static_cast<std::size_t>(raven::index(arm))];
  return (ArmJoints::Ones() + m.gravity_error)
      .cwiseProduct(twin::gravityCompensation(arm, joints, twin::DriveTrain::raven2()));
}

TEST(WorldMotors, HeldStillTheMotorsCarryTheFittedWeight) {
  // Acceptance 1(c): frictionless, at rest, Tau is the weight the calibration fitted (the
  // firmware's estimate and the fitted gravity error), whatever the links of the model weigh.
  twin::TwinOptions options = frictionlessMotors();
  auto shipped = twin::CalibrationProfile::shipped().mechanics;
  for (std::size_t a = 0; a < 2; ++a) (*options.motors)[a].gravity_error = shipped[a].gravity_error;
  auto motors = test_support::readyTwin(options);
  motors->advance(3.0);  // the integrators take up what the compensation misses
  // Held, a motor hunts by an encoder count about its setpoint (kp x 1.6 mrad is about 0.015
  // N m on a shoulder): its torque balances the load on average, over a second.
  std::array<ArmJoints, 2> mean_tau{ArmJoints::Zero(), ArmJoints::Zero()};
  constexpr int kCycles = 1000;
  for (int k = 0; k < kCycles; ++k) {
    motors->advance(0.001);
    for (Arm arm : raven::kArms) {
      mean_tau[static_cast<std::size_t>(raven::index(arm))] += loggedTau(*motors, arm) / kCycles;
    }
  }
  for (Arm arm : raven::kArms) {
    const ArmJoints expected = fittedWeight(options, arm, motors->measuredJs(arm).position);
    const ArmJoints tau = mean_tau[static_cast<std::size_t>(raven::index(arm))];
    const double scale = expected.cwiseAbs().maxCoeff();
    for (int i = 0; i < raven::kJointCount; ++i) {
      EXPECT_NEAR(tau(i), expected(i), 0.05 * std::abs(expected(i)) + 1e-3 * scale)
          << raven::armName(arm) << " " << raven::kJointNames[static_cast<std::size_t>(i)];
    }
  }
}

/// `arm`'s joints and, per joint, the bodies it moves (its child and everything beyond).
struct ArmChain {
  std::vector<const ambf_like::Joint*> joints;
  std::vector<std::vector<std::string>> moves;  ///< qualified body names, per joint
};

ArmChain chainOf(twin::TwinPlatform& twin, Arm arm) {
  ambf_like::World& world = twin.world();
  ArmChain chain;
  const auto names =
      twin::ArmBindings::ourRaven().joints[static_cast<std::size_t>(raven::index(arm))];
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

/// J^T F: the joint loads (N m, N) the last step's contacts on `arm`'s bodies put on its joints,
/// each contact force taken about the joint's axis through its pivot as the World has them now.
ArmJoints contactLoads(twin::TwinPlatform& twin, Arm arm) {
  ambf_like::World& world = twin.world();
  const ArmChain chain = chainOf(twin, arm);
  ArmJoints loads = ArmJoints::Zero();
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

/// Our Raven-II with a static 3 x 3 x 1 cm slab at `centre` (world), its faces across `normal`.
twin::TwinOptions withSlab(const twin::TwinOptions& base, const Eigen::Vector3d& centre,
                           const Eigen::Vector3d& normal) {
  twin::TwinOptions options = base;
  options.adjust_scene = [centre, normal](ambf_like::SceneSpec& scene) {
    ambf_like::ModelSpec slab;
    slab.name_space = "/test/";
    ambf_like::BodySpec body;
    body.name = "slab";
    ambf_like::PrimitiveShape box;
    box.box_size = Eigen::Vector3d(0.03, 0.03, 0.01);
    box.offset = ambf_like::Transform::Identity();
    body.collision.primitives.push_back(box);
    body.location.translation() = centre;
    body.location.linear() =
        Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), normal).toRotationMatrix();
    slab.bodies.push_back(body);
    scene.models.push_back(slab);
  };
  return options;
}

TEST(WorldMotors, AToolPressedOnASlabLoadsTheArmMotorsWithJTransposeF) {
  // Acceptance 1(b): the arm at rest with the tool pressed on a rigid slab; the motors' joint
  // loads less the weight they carry equal J^T F of the contact forces.
  const twin::TwinOptions motors_only = frictionlessMotors();
  const auto probe = test_support::readyTwin(motors_only);
  ambf_like::World& free_world = probe->world();
  // The slab 3 cm ahead of the jaws at home, across the insertion's axis: on the side away
  // from the shaft, where withdrawing the insertion takes them in this model's frames.
  const auto& insertion = *chainOf(*probe, Arm::Left).joints[raven::kInsertion];
  const Eigen::Vector3d axis =
      free_world.body("/raven2/left/" + insertion.spec().parent).pose().linear() *
      insertion.spec().parent_axis.normalized();
  const Eigen::Vector3d jaw = free_world.body("/raven2/left/jaw1_link").pose().translation();
  auto pressed = test_support::readyTwin(withSlab(motors_only, jaw - 0.03 * axis, axis));
  ambf_like::World& world = pressed->world();
  const ArmChain chain = chainOf(*pressed, Arm::Left);
  auto touching = [&] {
    for (const auto& body : chain.moves[raven::kInsertion]) {
      if (!world.contacts(body).empty()) return true;
    }
    return false;
  };
  ArmJoints in = ArmJoints::Zero();
  in(raven::kInsertion) = -2e-5;  // 2 cm/s toward the slab
  for (int k = 0; k < 8000 && !touching(); ++k) {
    pressed->send(bridge::ServoJr{Arm::Left, in});
    pressed->advance(0.001);
  }
  ASSERT_TRUE(touching()) << "the tool never reached the slab";
  for (int k = 0; k < 150; ++k) {  // 3 mm into it
    pressed->send(bridge::ServoJr{Arm::Left, in});
    pressed->advance(0.001);
  }
  pressed->advance(2.0);
  // Pressed, the arm stands still while its tool motors hunt by an encoder count: motors and
  // contacts balance on average, over 0.3 s.
  const auto drive = twin::DriveTrain::raven2();
  const auto c = drive.coupling(Arm::Left);
  ArmJoints by_motors = ArmJoints::Zero();
  ArmJoints by_contact = ArmJoints::Zero();
  constexpr int kCycles = 300;
  for (int k = 0; k < kCycles; ++k) {
    pressed->advance(0.001);
    for (int j = 0; j <= raven::kInsertion; ++j) {
      ASSERT_LT(std::abs(chain.joints[static_cast<std::size_t>(j)]->velocity()), 1e-3);
    }
    const ArmJoints tau = appliedTorque(*pressed, Arm::Left);
    by_motors += c.transpose() * tau.cwiseQuotient(drive.gearbox) / kCycles;
    by_contact += contactLoads(*pressed, Arm::Left) / kCycles;
  }
  // At rest the motors' joint loads carry the fitted weight and push against the contact.
  const ArmJoints weight =
      c.transpose() * fittedWeight(motors_only, Arm::Left, pressed->measuredJs(Arm::Left).position)
                          .cwiseQuotient(drive.gearbox);
  const ArmJoints expected = weight - by_contact;
  EXPECT_GT(by_contact.cwiseAbs().maxCoeff(), 1.0) << "pressed with less than 1 N";
  // The insertion, which the slab stops, within 5 %; the shoulder and elbow, which hold the
  // contact's moment while the tool motors still settle (the rotors feel a contact only step by
  // step, through the links' own inertia: see docs/actuation.md), within 25 %.
  for (int j = 0; j <= raven::kInsertion; ++j) {
    const double share = j == raven::kInsertion ? 0.05 : 0.25;
    EXPECT_NEAR(by_motors(j), expected(j), share * std::abs(by_contact(j)) + 2e-3)
        << raven::kJointNames[static_cast<std::size_t>(j)] << ": contact " << by_contact(j)
        << ", weight " << weight(j);
  }
}

}  // namespace
