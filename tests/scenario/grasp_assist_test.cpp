// The grasp assist's trigger rule on the real grasper: it takes a peg only while the jaws close
// and only when both jaws touch it, and lets it go (anchors removed) once they open again.

#include "scenario/grasp_assist.hpp"

#include <BulletCollision/CollisionShapes/btConvexShape.h>
#include <BulletDynamics/Dynamics/btRigidBody.h>
#include <BulletSoftBody/btSoftBody.h>
#include <gtest/gtest.h>

#include "bridge/twin_platform.hpp"

namespace {

using raven::Arm;

/// A point inside a jaw's convex collision shape: the mean of its six axis-extreme support
/// points (a convex combination of points of the shape).
btVector3 insideOf(const ambf_like::RigidBody& jaw) {
  const btRigidBody& body = jaw.bullet();
  const auto* shape = dynamic_cast<const btConvexShape*>(body.getCollisionShape());
  const btTransform& pose = body.getWorldTransform();
  btVector3 sum(0, 0, 0);
  for (int axis = 0; axis < 3; ++axis) {
    for (double sign : {-1.0, 1.0}) {
      btVector3 direction(0, 0, 0);
      direction[axis] = sign;
      sum += pose(
          shape->localGetSupportingVertexWithoutMargin(pose.getBasis().transpose() * direction));
    }
  }
  return sum / 6.0;
}

class GraspAssistTest : public ::testing::Test {
 protected:
  GraspAssistTest() : twin_(options()), assist_(twin_.world(), {"peg1", "peg2"}) {}
  static bridge::TwinOptions options() {
    bridge::TwinOptions o;
    o.launch_file = raven::modelDirectory() / "peg_transfer" / "launch.yaml";
    return o;
  }
  ambf_like::RigidBody& jaw(int which) {
    return twin_.world().body("/raven2/left/jaw" + std::to_string(which) + "_link");
  }
  btSoftBody& peg() { return twin_.world().softBody("peg1").bullet(); }

  bridge::TwinPlatform twin_;
  scenario::GraspAssist assist_;
};

TEST_F(GraspAssistTest, NothingIsTakenWhenNoJawTouches) {
  assist_.update(Arm::Left, 1.0);
  assist_.update(Arm::Left, 0.5);  // closing, far from every peg
  EXPECT_EQ(assist_.held(Arm::Left), nullptr);
  EXPECT_EQ(assist_.grasps(), 0u);
}

TEST_F(GraspAssistTest, OneJawTouchingIsNotAGrasp) {
  peg().m_nodes[0].m_x = insideOf(jaw(1));
  ASSERT_FALSE(assist_.touching(twin_.world().softBody("peg1"), jaw(1)).empty());
  ASSERT_TRUE(assist_.touching(twin_.world().softBody("peg1"), jaw(2)).empty());
  assist_.update(Arm::Left, 1.0);
  assist_.update(Arm::Left, 0.5);
  EXPECT_EQ(assist_.held(Arm::Left), nullptr);
}

TEST_F(GraspAssistTest, BothJawsTouchingTakesThePegOnlyWhileClosingAndOpeningLetsItGo) {
  peg().m_nodes[0].m_x = insideOf(jaw(1));
  peg().m_nodes[1].m_x = insideOf(jaw(2));
  assist_.update(Arm::Left, 0.5);
  assist_.update(Arm::Left, 0.6);  // opening: contact alone takes nothing
  EXPECT_EQ(assist_.held(Arm::Left), nullptr);

  assist_.update(Arm::Left, 0.4);  // closing on it
  ASSERT_EQ(assist_.held(Arm::Left), &twin_.world().softBody("peg1"));
  EXPECT_EQ(assist_.grasps(), 1u);
  EXPECT_GE(peg().m_anchors.size(), 2);
  EXPECT_EQ(assist_.held(Arm::Right), nullptr);

  assist_.update(Arm::Left, 0.3);   // tighter
  assist_.update(Arm::Left, 0.34);  // a little looser: still held
  EXPECT_NE(assist_.held(Arm::Left), nullptr);
  assist_.update(Arm::Left, 0.36);  // 0.06 rad past the tightest: let go
  EXPECT_EQ(assist_.held(Arm::Left), nullptr);
  EXPECT_EQ(peg().m_anchors.size(), 0);
}

}  // namespace
