// A two-link arm written as URDF behaves exactly like the same arm written as ADF.

#include <gtest/gtest.h>

#include "test_files.hpp"

namespace {

const char* kUrdf = R"(<?xml version="1.0"?>
<robot name="arm">
  <link name="base">
    <collision><geometry><box size="0.1 0.1 0.1"/></geometry></collision>
  </link>
  <link name="upper">
    <inertial>
      <origin xyz="0.15 0 0"/>
      <mass value="1.0"/>
      <inertia ixx="0.001" ixy="0" ixz="0" iyy="0.0085" iyz="0" izz="0.0086"/>
    </inertial>
    <collision><origin xyz="0.15 0 0"/><geometry><box size="0.3 0.04 0.04"/></geometry></collision>
  </link>
  <link name="fore">
    <inertial>
      <origin xyz="0.1 0 0"/>
      <mass value="0.5"/>
      <inertia ixx="0.0005" ixy="0" ixz="0" iyy="0.002" iyz="0" izz="0.0021"/>
    </inertial>
    <collision><origin xyz="0.1 0 0"/><geometry><box size="0.2 0.03 0.03"/></geometry></collision>
  </link>
  <joint name="shoulder" type="revolute">
    <parent link="base"/><child link="upper"/>
    <origin xyz="0 0 0.5" rpy="0 0 0"/><axis xyz="0 1 0"/>
    <limit lower="-2" upper="2" effort="10" velocity="3"/>
  </joint>
  <joint name="elbow" type="revolute">
    <parent link="upper"/><child link="fore"/>
    <origin xyz="0.3 0 0" rpy="0 0 0"/><axis xyz="0 1 0"/>
    <limit lower="-2.5" upper="2.5" effort="10" velocity="3"/>
  </joint>
</robot>
)";

const char* kAdf = R"(bodies: [BODY base, BODY upper, BODY fore]
joints: [JOINT shoulder, JOINT elbow]
namespace: /ambf/env/arm/
BODY base:
  name: base
  mass: 0
  collision shape: BOX
  collision geometry: {x: 0.1, y: 0.1, z: 0.1}
BODY upper:
  name: upper
  mass: 1.0
  inertia: {ix: 0.001, iy: 0.0085, iz: 0.0086}
  inertial offset: {position: {x: 0.15, y: 0, z: 0}}
  collision shape: BOX
  collision geometry: {x: 0.3, y: 0.04, z: 0.04}
  collision offset: {position: {x: 0.15, y: 0, z: 0}}
  location: {position: {x: 0, y: 0, z: 0.5}}
BODY fore:
  name: fore
  mass: 0.5
  inertia: {ix: 0.0005, iy: 0.002, iz: 0.0021}
  inertial offset: {position: {x: 0.1, y: 0, z: 0}}
  collision shape: BOX
  collision geometry: {x: 0.2, y: 0.03, z: 0.03}
  collision offset: {position: {x: 0.1, y: 0, z: 0}}
  location: {position: {x: 0.3, y: 0, z: 0.5}}
JOINT shoulder:
  name: shoulder
  parent: BODY base
  child: BODY upper
  parent pivot: {x: 0, y: 0, z: 0.5}
  parent axis: {x: 0, y: 1, z: 0}
  child axis: {x: 0, y: 1, z: 0}
  type: revolute
  joint limits: {low: -2, high: 2}
JOINT elbow:
  name: elbow
  parent: BODY upper
  child: BODY fore
  parent pivot: {x: 0.3, y: 0, z: 0}
  parent axis: {x: 0, y: 1, z: 0}
  child axis: {x: 0, y: 1, z: 0}
  type: revolute
  joint limits: {low: -2.5, high: 2.5}
)";

TEST(Urdf, TwoLinkArmMatchesTheSameArmWrittenAsAdf) {
  test_support::TempDir dir;
  auto urdf = test_support::simulate({dir.write("arm.urdf", kUrdf)});
  auto adf = test_support::simulate({dir.write("arm.yaml", kAdf)});
  auto& u = *urdf->world;
  auto& a = *adf->world;
  ASSERT_EQ(u.bodyCount(), 3u);
  ASSERT_EQ(u.jointCount(), 2u);
  EXPECT_EQ(u.joint("/ambf/env/arm/elbow").spec().limits->high, 2.5);

  double worst_joint = 0.0, worst_body = 0.0;
  auto compare = [&] {
    for (const char* j : {"shoulder", "elbow"}) {
      worst_joint = std::max(worst_joint, std::abs(u.joint(j).position() - a.joint(j).position()));
    }
    for (const char* b : {"upper", "fore"}) {
      worst_body = std::max(
          worst_body, (u.body(b).pose().translation() - a.body(b).pose().translation()).norm());
    }
  };
  // Half a second of free fall under gravity, then both joints driven to new positions.
  for (int i = 0; i < 500; ++i) {
    u.step();
    a.step();
    compare();
  }
  EXPECT_GT(std::abs(a.joint("shoulder").position()), 0.1) << "the arm should have swung";
  for (auto* world : {&u, &a}) {
    world->joint("shoulder").commandPosition(-0.4);
    world->joint("elbow").commandPosition(0.9);
  }
  for (int i = 0; i < 2000; ++i) {
    u.step();
    a.step();
    compare();
  }
  EXPECT_LT(worst_joint, 1e-6);
  EXPECT_LT(worst_body, 1e-6);
  EXPECT_NEAR(u.joint("elbow").position(), 0.9, 0.05);
}

}  // namespace
