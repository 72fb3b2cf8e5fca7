// Bodies dropped on a plane come to rest on it: no tunnelling, no floating by the margin.

#include <BulletDynamics/Dynamics/btRigidBody.h>
#include <BulletSoftBody/btSoftBody.h>
#include <gtest/gtest.h>

#include <algorithm>

#include "test_files.hpp"

namespace {

using test_support::softBallBody;

const std::string kGround = test_support::groundPlaneBody();

TEST(Contact, BoxDroppedOnAPlaneRestsOnIt) {
  test_support::TempDir dir;
  const auto file = dir.write("drop.yaml", "bodies: [BODY ground, BODY box]\n" + kGround +
                                               "BODY box:\n"
                                               "  name: box\n"
                                               "  mass: 0.5\n"
                                               "  collision shape: BOX\n"
                                               "  collision geometry: {x: 0.1, y: 0.1, z: 0.1}\n"
                                               "  location: {position: {x: 0, y: 0, z: 1.0}}\n");
  auto sim = test_support::simulate({file});
  auto& world = *sim->world;
  // A static PLANE is Bullet's half-space, as AMBF makes it (vertex-plane contacts).
  EXPECT_EQ(world.body("ground").bullet().getCollisionShape()->getShapeType(),
            STATIC_PLANE_PROXYTYPE);
  auto& box = world.body("box");
  double lowest = 1.0;
  while (world.time() < 3.0) {
    world.step();
    lowest = std::min(lowest, box.pose().translation().z());
  }
  const double rest = box.pose().translation().z();
  EXPECT_GT(lowest, 0.05 - 0.005) << "the box sank into the plane";
  EXPECT_NEAR(rest, 0.05, 1e-3) << "the box should rest with its face on the plane";
  EXPECT_LT(box.linearVelocity().norm(), 1e-3);

  const auto contacts = world.contacts();
  ASSERT_FALSE(contacts.empty());
  const auto& c = contacts.front();
  EXPECT_TRUE((c.body_a == "/ambf/env/box" && c.body_b == "/ambf/env/ground") ||
              (c.body_b == "/ambf/env/box" && c.body_a == "/ambf/env/ground"));
  EXPECT_NEAR(std::abs(c.normal_on_b.z()), 1.0, 1e-6);
  EXPECT_LE(c.distance, 1e-3);
}

TEST(Contact, ABodysContactsAreExactlyTheOnesThatTouchIt) {
  test_support::TempDir dir;
  auto box = [](const std::string& name, double x) {
    return "BODY " + name + ":\n  name: " + name +
           "\n  mass: 0.5\n  collision shape: BOX\n  collision geometry: {x: 0.1, y: 0.1, z: 0.1}\n"
           "  location: {position: {x: " +
           std::to_string(x) + ", y: 0, z: 0.06}}\n";
  };
  const auto file = dir.write("two.yaml", "bodies: [BODY ground, BODY left, BODY right]\n" +
                                              kGround + box("left", -0.5) + box("right", 0.5));
  auto sim = test_support::simulate({file});
  auto& world = *sim->world;
  world.step(500);
  auto touches = [](const ambf_like::Contact& c, const std::string& body) {
    return c.body_a == body || c.body_b == body;
  };
  const auto all = world.contacts();
  for (const std::string body : {"/ambf/env/left", "/ambf/env/right"}) {
    const auto own = world.contacts(body);
    const auto expected =
        std::count_if(all.begin(), all.end(), [&](const auto& c) { return touches(c, body); });
    ASSERT_GT(expected, 0) << body << " rests on the ground";
    EXPECT_EQ(static_cast<long>(own.size()), expected) << body;
    for (const auto& c : own) EXPECT_TRUE(touches(c, body)) << c.body_a << " - " << c.body_b;
  }
  EXPECT_LT(world.contacts("/ambf/env/left").size(), all.size());
  EXPECT_THROW(world.contacts("no_such_body"), std::out_of_range);
}

/// A 10 cm cube mesh as a dynamic body of the given collision mesh type, dropped on the plane.
double restingHeightOfCubeMesh(const std::string& mesh_type) {
  test_support::TempDir dir;
  dir.write("cube.obj",
            "v -0.05 -0.05 -0.05\nv 0.05 -0.05 -0.05\nv 0.05 0.05 -0.05\nv -0.05 0.05 -0.05\n"
            "v -0.05 -0.05 0.05\nv 0.05 -0.05 0.05\nv 0.05 0.05 0.05\nv -0.05 0.05 0.05\n"
            "f 1 3 2\nf 1 4 3\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\n"
            "f 2 3 7\nf 2 7 6\nf 3 4 8\nf 3 8 7\nf 4 1 5\nf 4 5 8\n");
  const auto file = dir.write("drop.yaml", "bodies: [BODY ground, BODY cube]\n" + kGround +
                                               "BODY cube:\n"
                                               "  name: cube\n"
                                               "  mass: 0.5\n"
                                               "  mesh: cube.obj\n"
                                               "  collision mesh type: " +
                                               mesh_type +
                                               "\n"
                                               "  location: {position: {x: 0, y: 0, z: 0.5}}\n");
  auto sim = test_support::simulate({file});
  sim->world->step(3000);
  return sim->world->body("cube").pose().translation().z();
}

TEST(Contact, EveryCollisionMeshTypeRestsOnThePlane) {
  for (const char* type : {"CONCAVE_MESH", "CONVEX_MESH", "CONVEX_HULL"}) {
    // GImpact meshes keep their margin outside the surface, hence the looser bound.
    EXPECT_NEAR(restingHeightOfCubeMesh(type), 0.05, 2.5e-3) << type;
  }
}

TEST(Contact, SoftBodyDroppedOnAPlaneRestsOnIt) {
  test_support::TempDir dir;
  const double margin = 0.002;
  const auto file = dir.write(
      "drop.yaml", "bodies: [BODY ground]\nsoft bodies: [BODY blob]\n" + kGround +
                       softBallBody(margin) +
                       "  location: {position: {x: 0, y: 0, z: 0.3}}\n"
                       "  config: {kDF: 0.8, kVC: 20, piterations: 4, bending constraint: 2}\n");
  auto sim = test_support::simulate({file});
  auto& world = *sim->world;
  auto& blob = world.softBody("blob");
  double lowest_ever = 1.0;
  while (world.time() < 3.0) {
    world.step();
    for (const auto& p : blob.nodePositions()) lowest_ever = std::min(lowest_ever, p.z());
  }
  ASSERT_TRUE(blob.isFinite());
  double lowest = 1.0, highest = -1.0;
  for (const auto& p : blob.nodePositions()) {
    lowest = std::min(lowest, p.z());
    highest = std::max(highest, p.z());
  }
  EXPECT_GT(lowest_ever, -0.01) << "nodes tunnelled through the plane";
  // At rest the lowest nodes sit on the plane, held off it by at most the collision margin
  // (Bullet's default margin of 0.25 m would leave the 5 cm ball floating in the air).
  EXPECT_GT(lowest, -0.002);
  EXPECT_LT(lowest, margin + 0.002);
  EXPECT_GT(highest, 0.05) << "the ball collapsed flat";
  // It rests on the plane's proxy (soft bodies cannot rest on a half-space), which reads as
  // the plane.
  bool touching = false;
  for (const auto& c : world.contacts()) {
    touching |= c.body_a == "/ambf/env/blob" && c.body_b == "/ambf/env/ground";
  }
  EXPECT_TRUE(touching);
}

TEST(Contact, SoftBodyNodeBoundsAreSizedByItsOwnMargin) {
  // Each node's bounding-volume leaf must be the node plus the body's margin: leaves left at
  // Bullet's 0.25 m default make every rigid body within 25 cm test every node at every step
  // (the peg-transfer scene ran at half speed, and the coarse distance field then caught nodes up
  // to a voxel outside a shape's bounds).
  test_support::TempDir dir;
  const double margin = 0.0005;
  const auto file = dir.write("blob.yaml", "soft bodies: [BODY blob]\n" + softBallBody(margin));
  auto sim = test_support::simulate({file});
  auto& body = sim->world->softBody("blob").bullet();
  for (int step = 0; step < 2; ++step) {
    for (int i = 0; i < body.m_nodes.size(); ++i) {
      const btVector3 half_extent = body.m_nodes[i].m_leaf->volume.Extents();
      EXPECT_LT(half_extent.length(), 4 * margin) << "node " << i << " at step " << step;
    }
    sim->world->step();
  }
}

}  // namespace
