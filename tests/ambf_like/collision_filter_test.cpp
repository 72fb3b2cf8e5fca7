// Collision groups and `ignore inter-collision` decide which bodies meet.

#include "ambf_like/dynamics/collision_filter.hpp"

#include <BulletCollision/CollisionShapes/btBoxShape.h>
#include <BulletSoftBody/btSoftBody.h>
#include <BulletSoftBody/btSoftBodyHelpers.h>
#include <gtest/gtest.h>

#include <memory>

#include "test_files.hpp"

namespace {

/// A static slab at z = 0 and a box dropped onto it, with the given groups; returns where the
/// box ends after one second (about 0.1 when it lands on the slab, far below when it passes).
double dropThroughSlab(const std::string& slab_groups, const std::string& box_groups,
                       bool ignore_inter_collision = false) {
  test_support::TempDir dir;
  const auto file = dir.write(
      "m.yaml", std::string("bodies: [BODY slab, BODY box]\n") +
                    "ignore inter-collision: " + (ignore_inter_collision ? "true" : "false") +
                    "\n"
                    "BODY slab: {name: slab, mass: 0, collision shape: BOX,"
                    " collision geometry: {x: 1, y: 1, z: 0.1}, collision groups: " +
                    slab_groups +
                    "}\n"
                    "BODY box: {name: box, mass: 1, collision shape: BOX,"
                    " collision geometry: {x: 0.1, y: 0.1, z: 0.1}, collision groups: " +
                    box_groups + ", location: {position: {x: 0, y: 0, z: 0.5}}}\n");
  auto sim = test_support::simulate({file});
  sim->world->step(1000);
  return sim->world->body("box").pose().translation().z();
}

TEST(CollisionFilter, BodiesSharingAGroupCollide) {
  EXPECT_NEAR(dropThroughSlab("[1, 4]", "[4]"), 0.1, 2e-3);
}

TEST(CollisionFilter, BodiesWithDisjointGroupsPassThroughEachOther) {
  EXPECT_LT(dropThroughSlab("[1]", "[2, 3]"), -1.0);
}

TEST(CollisionFilter, AnEmptyGroupListCollidesWithEveryGroup) {
  EXPECT_NEAR(dropThroughSlab("[]", "[7]"), 0.1, 2e-3);
}

TEST(CollisionFilter, IgnoreInterCollisionSeparatesBodiesOfOneModel) {
  EXPECT_LT(dropThroughSlab("[]", "[]", true), -1.0);
  EXPECT_NEAR(dropThroughSlab("[]", "[]", false), 0.1, 2e-3);
}

TEST(CollisionFilter, IgnoreInterCollisionStillCollidesWithOtherModels) {
  test_support::TempDir dir;
  const auto slab = dir.write("slab.yaml",
                              "bodies: [BODY slab]\nignore inter-collision: true\n"
                              "BODY slab: {name: slab, mass: 0, collision shape: BOX,"
                              " collision geometry: {x: 1, y: 1, z: 0.1}}\n");
  const auto box = dir.write("box.yaml",
                             "bodies: [BODY box]\nignore inter-collision: true\n"
                             "BODY box: {name: box, mass: 1, collision shape: BOX,"
                             " collision geometry: {x: 0.1, y: 0.1, z: 0.1},"
                             " location: {position: {x: 0, y: 0, z: 0.5}}}\n");
  auto sim = test_support::simulate({slab, box});
  sim->world->step(1000);
  EXPECT_NEAR(sim->world->body("box").pose().translation().z(), 0.1, 2e-3);
}

/// The filter's answer for a pair of collision objects, as the broadphase asks it.
bool filterLetsMeet(btCollisionObject& a, btCollisionObject& b) {
  const btVector3 low(-1, -1, -1), high(1, 1, 1);
  btBroadphaseProxy pa(low, high, &a, btBroadphaseProxy::DefaultFilter,
                       btBroadphaseProxy::AllFilter);
  btBroadphaseProxy pb(low, high, &b, btBroadphaseProxy::DefaultFilter,
                       btBroadphaseProxy::AllFilter);
  const ambf_like::detail::CollisionFilter filter;
  return filter.needBroadphaseCollision(&pa, &pb) && filter.needBroadphaseCollision(&pb, &pa);
}

TEST(CollisionFilter, ASoftBodyMeetsOnlyWhatItsCollisionModesMakeSomethingOf) {
  using Collision = btSoftBody::fCollision;
  btSoftBodyWorldInfo info;
  auto patch = [&info](int modes) {
    std::unique_ptr<btSoftBody> soft(
        btSoftBodyHelpers::CreatePatch(info, btVector3(0, 0, 0), btVector3(1, 0, 0),
                                       btVector3(0, 1, 0), btVector3(1, 1, 0), 3, 3, 0, false));
    soft->m_cfg.collisions = modes;
    return soft;
  };
  btBoxShape box(btVector3(0.1, 0.1, 0.1));
  btCollisionObject rigid;
  rigid.setCollisionShape(&box);
  const auto soft_only = patch(Collision::VF_SS);  // AMBF's cloth: flags 16
  const auto rigid_too = patch(Collision::SDF_RS | Collision::VF_SS);
  const auto rigid_only = patch(Collision::SDF_RS);
  EXPECT_FALSE(filterLetsMeet(*soft_only, rigid));
  EXPECT_TRUE(filterLetsMeet(*rigid_too, rigid));
  EXPECT_TRUE(filterLetsMeet(*soft_only, *rigid_too));  // VF_SS in common
  EXPECT_FALSE(filterLetsMeet(*soft_only, *rigid_only));
  EXPECT_FALSE(filterLetsMeet(*rigid_only, *rigid_only));
}

}  // namespace
