// The contacts of an elastic body's node: a node caught between two surfaces that close on it
// passes no load from one to the other, however long it stays caught.

#include "ambf_like/dynamics/elastic_contacts.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace {

using ambf_like::detail::ElasticContact;
using ambf_like::detail::ElasticContactSolver;
using ambf_like::detail::NodeResponse;

constexpr double kNodeMass = 1e-5;  // kg: a node of a 1.4 g ring of 144 nodes

/// A free node: an impulse p changes its velocity by p / m.
NodeResponse freeNode() {
  return NodeResponse::Identity(3, 3) / kNodeMass;
}

/// A contact of node 0 with a surface facing `normal`, from which the node must leave at
/// `least` (m/s) to end the step on it.
ElasticContact contactOf(const Eigen::Vector3d& normal, double least, double friction) {
  ElasticContact c;
  c.normal = normal.normalized();
  c.least_normal_velocity = least;
  c.friction = friction;
  return c;
}

double normalImpulse(const ElasticContact& c) {
  return c.normal.dot(c.impulse);
}

/// Solves `contacts` on one free node at rest `steps` times, each warm started from the last.
void solveSteps(std::vector<ElasticContact>& contacts, int steps) {
  ElasticContactSolver solver;
  const NodeResponse response = freeNode();
  const Eigen::VectorXd rest = Eigen::VectorXd::Zero(3);
  for (int s = 0; s < steps; ++s) {
    solver.solve(rest, contacts, [&](int) -> const NodeResponse& { return response; });
  }
}

TEST(ElasticContacts, ANodeCaughtBetweenSurfacesClosingOnItPassesNoLoadFromOneToTheOther) {
  // A floor and a ceiling 0.2 mm inside each other over one 1 ms step: the node cannot leave
  // both. Whatever it does, neither surface may push it against the other.
  std::vector<ElasticContact> contacts{contactOf({0, 0, 1}, 0.1, 0.0),
                                       contactOf({0, 0, -1}, 0.1, 0.0)};
  solveSteps(contacts, 1);
  EXPECT_DOUBLE_EQ(std::min(normalImpulse(contacts[0]), normalImpulse(contacts[1])), 0.0);
  // What pushes is what moves the node out of one of them: m v, no more.
  const double pushed = std::max(normalImpulse(contacts[0]), normalImpulse(contacts[1]));
  EXPECT_NEAR(pushed, kNodeMass * 0.1, 1e-12);
}

TEST(ElasticContacts, ANodeCaughtStepAfterStepIsPushedNoHarderThanOnTheFirst) {
  // Warm started, the opposed impulses grew by what every sweep added, step after step.
  std::vector<ElasticContact> once{contactOf({0.1, 0, 1}, 0.1, 0.8),
                                   contactOf({0.2, 0.1, -1}, 0.05, 0.8)};
  std::vector<ElasticContact> often = once;
  solveSteps(once, 1);
  solveSteps(often, 50);
  for (std::size_t k = 0; k < once.size(); ++k) {
    EXPECT_LT(often[k].impulse.norm(), 2.0 * kNodeMass * 0.15) << "contact " << k;
    EXPECT_LE(often[k].impulse.norm(), 1.01 * once[k].impulse.norm() + 1e-12) << "contact " << k;
    // Each within its cone, pushing or not at all.
    const double normal = normalImpulse(often[k]);
    EXPECT_GE(normal, -1e-15);
    EXPECT_LE((often[k].impulse - often[k].normal * normal).norm(), 0.8 * normal + 1e-12);
  }
}

TEST(ElasticContacts, ANodeWithRoomBetweenTwoSurfacesIsPushedOnlyByTheOneItMeets) {
  // The ceiling leaves room (the node may move up 0.1 m/s and still stay under it): the floor
  // lifts the node as it would alone.
  std::vector<ElasticContact> contacts{contactOf({0, 0, 1}, 0.05, 0.5),
                                       contactOf({0, 0, -1}, -0.1, 0.5)};
  solveSteps(contacts, 1);
  EXPECT_NEAR(normalImpulse(contacts[0]), kNodeMass * 0.05, 1e-12);
  EXPECT_DOUBLE_EQ(contacts[1].impulse.norm(), 0.0);
}

TEST(ElasticContacts, ANodeCaughtBetweenAFixedSurfaceAndAMovingOneStaysOnTheFixedOne) {
  // The board below, a jaw 0.2 mm into it from above: the node is pushed out of the board
  // alone, and the jaw, which the board will stop, is not pushed by it.
  ElasticContact board = contactOf({0, 0, 1}, 0.1, 0.5);
  board.fixed_surface = true;
  std::vector<ElasticContact> contacts{contactOf({0, 0, -1}, 0.1, 0.5), board};
  solveSteps(contacts, 3);
  EXPECT_DOUBLE_EQ(contacts[0].impulse.norm(), 0.0);
  EXPECT_NEAR(normalImpulse(contacts[1]), kNodeMass * 0.1, 1e-12);
}

}  // namespace
