// Two-way coupling: a free rigid body that presses on an elastic body's nodes takes their
// reaction within the solve, so that both end as the momentum balance of a sticking (perfectly
// inelastic) contact says, however light the body is.

#include <gtest/gtest.h>

#include <vector>

#include "ambf_like/dynamics/elastic_contacts.hpp"

namespace elastic_contact_bodies_test {  // named: the unity build shares one file's unnamed one
namespace {

using ambf_like::detail::ContactBody;
using ambf_like::detail::ElasticContact;
using ambf_like::detail::ElasticContactSolver;
using ambf_like::detail::NodeResponse;

constexpr double kNodeMass = 1e-5;  // kg: a node of a 1.4 g ring of 144 nodes
constexpr double kApproach = 0.1;   // m/s: how fast the body's surface comes up at the nodes

/// `nodes` free nodes: an impulse on one changes its velocity alone, by p / m.
std::vector<NodeResponse> freeNodes(int nodes) {
  std::vector<NodeResponse> responses;
  for (int i = 0; i < nodes; ++i) {
    NodeResponse response = NodeResponse::Zero(3 * nodes, 3);
    response.middleRows<3>(3 * i) = Eigen::Matrix3d::Identity() / kNodeMass;
    responses.push_back(response);
  }
  return responses;
}

/// Node `node` just touched from below by a frictionless surface of body 0 (or of no moving
/// body) rising at kApproach, its point `arm` from the body's centre of mass.
ElasticContact touchedFromBelow(int node, const Eigen::Vector3d& arm, bool on_the_body) {
  ElasticContact c;
  c.node = node;
  c.normal = Eigen::Vector3d::UnitZ();
  c.surface_velocity = kApproach * Eigen::Vector3d::UnitZ();
  c.least_normal_velocity = kApproach;  // no gap: it must at least keep up
  c.body = on_the_body ? 0 : -1;
  c.arm = arm;
  return c;
}

/// Solves `contacts` on free nodes at rest, twice (the second warm started, through the stuck
/// solve); returns the impulses of both.
std::vector<std::vector<ElasticContact>> solveTwice(std::vector<ElasticContact> contacts,
                                                    const std::vector<ContactBody>& bodies,
                                                    int nodes) {
  ElasticContactSolver solver;
  const std::vector<NodeResponse> responses = freeNodes(nodes);
  const Eigen::VectorXd rest = Eigen::VectorXd::Zero(3 * nodes);
  std::vector<std::vector<ElasticContact>> solved;
  for (int s = 0; s < 2; ++s) {
    solver.solve(rest, contacts, bodies,
                 [&](int node) -> const NodeResponse& { return responses[node]; });
    solved.push_back(contacts);
  }
  return solved;
}

TEST(ElasticContactBodies, ABodyTwiceANodesMassEndsMovingWithItAtTwoThirdsOfItsSpeed) {
  // M u = (M + m) v: the node ends at M / (M + m) u, and takes m v.
  const double body_mass = 2.0 * kNodeMass;
  const ContactBody body{1.0 / body_mass, Eigen::Matrix3d::Identity()};
  for (const auto& solved :
       solveTwice({touchedFromBelow(0, Eigen::Vector3d::Zero(), true)}, {body}, 1)) {
    const double common = body_mass / (body_mass + kNodeMass) * kApproach;
    EXPECT_NEAR(solved[0].impulse.z(), kNodeMass * common, 1e-15);
    EXPECT_NEAR(solved[0].impulse.head<2>().norm(), 0.0, 1e-15);
  }
  // A surface no impulse moves (one-way) gives the node all of its own speed.
  const auto fixed = solveTwice({touchedFromBelow(0, Eigen::Vector3d::Zero(), false)}, {}, 1);
  EXPECT_NEAR(fixed[1][0].impulse.z(), kNodeMass * kApproach, 1e-15);
}

TEST(ElasticContactBodies, ALeverArmAddsItsTurningToTheBodysGive) {
  // Struck at r = (L, 0, 0) along z, the body gives 1/M + L^2 / I per unit impulse: the node
  // takes u / (1/m + 1/M + L^2/I).
  const double body_mass = 3.0 * kNodeMass;
  const double inertia = 2e-10;  // kg m^2 about y
  const double lever = 0.004;    // m
  ContactBody body{1.0 / body_mass, Eigen::Matrix3d::Identity() / inertia};
  const auto solved =
      solveTwice({touchedFromBelow(0, Eigen::Vector3d(lever, 0, 0), true)}, {body}, 1);
  const double expected =
      kApproach / (1.0 / kNodeMass + 1.0 / body_mass + lever * lever / inertia);
  for (const auto& s : solved) EXPECT_NEAR(s[0].impulse.z(), expected, 1e-9 * expected);
}

TEST(ElasticContactBodies, NodesPressedByOneBodyShareItsMomentum) {
  // One body on three nodes at its centre: M u = (M + 3 m) v, each node taking m v. Contacts
  // seen one at a time would each have ended at M / (M + m) u.
  const double body_mass = 2.0 * kNodeMass;
  const ContactBody body{1.0 / body_mass, Eigen::Matrix3d::Identity()};
  std::vector<ElasticContact> contacts;
  for (int node = 0; node < 3; ++node) {
    contacts.push_back(touchedFromBelow(node, Eigen::Vector3d::Zero(), true));
  }
  const double common = body_mass / (body_mass + 3.0 * kNodeMass) * kApproach;
  const auto solved = solveTwice(contacts, {body}, 3);
  // Gauss-Seidel alone stops once no impulse changes by 1e-8 N s; warm started, the stuck
  // solve takes all three at once.
  for (const auto& c : solved[0]) EXPECT_NEAR(c.impulse.z(), kNodeMass * common, 1e-8);
  for (const auto& c : solved[1]) EXPECT_NEAR(c.impulse.z(), kNodeMass * common, 1e-15);
}

}  // namespace
}  // namespace elastic_contact_bodies_test
