// A joint's damping is integrated exactly on the inertia it moves (issue 66): a light damper
// decays the joint's speed as exp(-c t / I), and a heavy one on a tiny link stops it within a
// step instead of flinging it (explicitly, c h / I above 2 grows the speed every step).

#include <BulletDynamics/Dynamics/btRigidBody.h>
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "test_files.hpp"

namespace {

using ambf_like::Articulation;

constexpr double kInertia = 1e-9;  ///< kg m^2 about the joint's axis: a link of 1 mg
/// What the link's own angular damping (AMBF's default, 0.1: Bullet keeps (1 - 0.1)^t of its
/// spin after t seconds) leaves of its speed after `seconds`.
double ownDampingKeeps(double seconds) {
  return std::pow(1.0 - 0.1, seconds);
}

/// A static base and a 1 mg link turning about z through its centre of mass, damped by `damping`
/// (N m s), without gravity; the joint spun to 1 rad/s.
std::unique_ptr<test_support::Simulation> spinningLink(test_support::TempDir& dir, double damping,
                                                       Articulation articulation) {
  std::ostringstream urdf;
  urdf << "<robot name='r'><link name='base'/><link name='l'><inertial><mass value='1e-6'/>"
       << "<inertia ixx='" << kInertia << "' iyy='" << kInertia << "' izz='" << kInertia
       << "' ixy='0' ixz='0' iyz='0'/></inertial></link><joint name='j' type='continuous'>"
       << "<parent link='base'/><child link='l'/><axis xyz='0 0 1'/><dynamics damping='" << damping
       << "'/></joint></robot>";
  auto sim = test_support::simulate({dir.write("link.urdf", urdf.str())},
                                    [articulation](ambf_like::WorldSpec& world) {
                                      world.articulation = articulation;
                                      world.gravity = ambf_like::Vec3::Zero();
                                    });
  auto& joint = sim->world->joint("j");
  if (joint.inArticulation()) {
    joint.place(0.0, 1.0);
  } else {
    sim->world->body("l").bullet().setAngularVelocity(btVector3(0, 0, 1));
  }
  return sim;
}

class JointDamping : public testing::TestWithParam<Articulation> {};

TEST_P(JointDamping, ALightDamperDecaysTheJointExponentially) {
  test_support::TempDir dir;
  const double damping = 10.0 * kInertia;  // c h / I = 0.01 at 1 ms: a time constant of 0.1 s
  auto sim = spinningLink(dir, damping, GetParam());
  ASSERT_NEAR(sim->world->joint("j").velocity(), 1.0, 1e-12);
  sim->world->step(100);
  // Both dampers act on each step's starting speed, so their shares add rather than compound:
  // 100 steps of 0.01 x 1e-4 leave the product 1e-4 apart.
  const double expected = std::exp(-damping * 0.1 / kInertia) * ownDampingKeeps(0.1);
  EXPECT_NEAR(sim->world->joint("j").velocity(), expected, 1.2e-4 * expected);
}

TEST_P(JointDamping, AHeavyDamperOnATinyLinkStopsItWithinAStep) {
  test_support::TempDir dir;
  auto sim = spinningLink(dir, 5.0, GetParam());  // c h / I = 5e6 at 1 ms
  // The damper takes the whole speed in the first step; the link's own damping, acting on the
  // same starting speed, takes its share (1e-4 of it) once more, and no more after that.
  const double own_share = 1.0 - ownDampingKeeps(0.001);
  double last = 1.0;
  for (int step = 0; step < 100; ++step) {
    sim->world->step();
    const double speed = std::abs(sim->world->joint("j").velocity());
    ASSERT_LE(speed, 1.01 * own_share * last + 1e-300) << "step " << step;  // to subnormals
    last = speed;
  }
}

INSTANTIATE_TEST_SUITE_P(BothFormulations, JointDamping,
                         testing::Values(Articulation::Maximal, Articulation::Reduced),
                         [](const auto& formulation) {
                           return formulation.param == Articulation::Maximal ? "Maximal"
                                                                             : "Reduced";
                         });

}  // namespace
