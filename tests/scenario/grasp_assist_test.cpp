// The grasp assist on the real grasper, as the scene's jaw sensors and actuators
// (peg_transfer/grasp_assist.yaml) triggered by the closing jaws: it takes a ring only while the
// jaws close and only when both jaws sense it, anchors what each jaw senses to that jaw, and lets
// it go (anchors removed) once they open again; its sensors cast rays only while the jaws close.

#include "scenario/grasp_assist.hpp"

#include <BulletSoftBody/btSoftBody.h>
#include <gtest/gtest.h>

#include <optional>

#include "ambf_like/scene_loader.hpp"
#include "one_arm_grasp.hpp"

namespace {

using raven::Arm;
using scenario::Phase;

/// The peg-transfer scene with the assist's model loaded after the arms.
twin::TwinOptions assistedScene() {
  return scenario_test::pegScene([](ambf_like::SceneSpec& scene) {
    ambf_like::appendModelFiles(scene, {scenario::GraspAssist::modelFile()});
  });
}

class GraspAssistTest : public scenario_test::OneArmGrasp {
 protected:
  GraspAssistTest() : OneArmGrasp(kDefaultSqueeze, assistedScene()) {
    assist_.emplace(world(), std::vector<std::string>{"ring1", "ring2"});
  }
  static constexpr double kDefaultSqueeze = scenario::ArmRoutine::kDefaultSqueeze;
  btSoftBody& ringBody() { return world().softBody("ring1").bullet(); }
  ambf_like::ProximitySensor& sensor(int jaw) {
    return world().sensor("left_jaw" + std::to_string(jaw) + "_sensor");
  }
  std::optional<scenario::GraspAssist> assist_;
};

TEST_F(GraspAssistTest, TheScenesJawsCarryItsSensorsAndActuators) {
  EXPECT_EQ(world().sensorCount(), 4u);
  EXPECT_EQ(world().actuatorCount(), 4u);
  EXPECT_EQ(sensor(1).parent().qualifiedName(), "/raven2/left/jaw1_link");
  EXPECT_EQ(world().actuator("right_jaw2_gripper").spec().parent, "/raven2/right/jaw2_link");
  EXPECT_FALSE(sensor(1).active()) << "idle until the jaws close";
}

TEST_F(GraspAssistTest, NothingIsTakenWhenNoJawSensesAPeg) {
  assist_->update(Arm::Left, 1.0);
  assist_->update(Arm::Left, 0.5);  // closing, far from every ring
  EXPECT_TRUE(sensor(1).active());
  hold(0.02);
  assist_->update(Arm::Left, 0.4);
  EXPECT_EQ(assist_->held(Arm::Left), nullptr);
  EXPECT_EQ(assist_->grasps(), 0u);
  assist_->update(Arm::Left, 0.6);  // opening: the sensors rest
  EXPECT_FALSE(sensor(1).active());
}

TEST_F(GraspAssistTest, OneJawSensingIsNotAGrasp) {
  runUntil(Phase::Close);  // down beside the wall, the outer jaw still open
  assist_->update(Arm::Left, routine_.opening() + 0.1);
  assist_->update(Arm::Left, routine_.opening());  // "closing": the sensors look
  hold(0.02);
  const auto& ring = world().softBody("ring1");
  ASSERT_FALSE(assist_->sensedNodes(Arm::Left, 0, ring).empty()) << "the inner jaw is at the wall";
  ASSERT_TRUE(assist_->sensedNodes(Arm::Left, 1, ring).empty()) << "the outer jaw is open";
  assist_->update(Arm::Left, routine_.opening() - 0.01);
  EXPECT_EQ(assist_->held(Arm::Left), nullptr);
  EXPECT_EQ(ringBody().m_anchors.size(), 0);
}

TEST_F(GraspAssistTest, BothJawsSensingTakesThePegWhileClosingAndOpeningLetsItGo) {
  runUntil(Phase::Lift, [&] { assist_->update(Arm::Left, routine_.opening()); });
  ASSERT_EQ(assist_->held(Arm::Left), &world().softBody("ring1"));
  EXPECT_EQ(assist_->grasps(), 1u);
  EXPECT_GE(ringBody().m_anchors.size(), 2);
  EXPECT_TRUE(world().actuator("left_jaw1_gripper").actuated());
  EXPECT_EQ(world().actuator("left_jaw2_gripper").heldBody(), "/peg_transfer/ring1");
  EXPECT_FALSE(sensor(1).active()) << "holding: nothing more to look for";
  EXPECT_EQ(assist_->held(Arm::Right), nullptr);

  const double closed = routine_.opening();
  assist_->update(Arm::Left, closed + 0.04);  // a little looser: still held
  EXPECT_NE(assist_->held(Arm::Left), nullptr);
  assist_->update(Arm::Left, closed + 0.06);  // 0.06 rad past the tightest: let go
  EXPECT_EQ(assist_->held(Arm::Left), nullptr);
  EXPECT_EQ(ringBody().m_anchors.size(), 0);
  EXPECT_FALSE(world().actuator("left_jaw1_gripper").actuated());
  assist_->update(Arm::Left, closed + 0.1);  // opening while touching takes nothing
  EXPECT_EQ(assist_->held(Arm::Left), nullptr);
}

}  // namespace
