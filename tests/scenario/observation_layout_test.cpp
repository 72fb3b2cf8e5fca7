// The learning environment's observation is laid out where scenario/observation_layout.hpp (and
// so Python's raven_sim.part) says: the parts tile it, and each named part holds what its name
// says, read from the twin itself.

#include "scenario/observation_layout.hpp"

#include <gtest/gtest.h>

#include "scenario/peg_transfer_env.hpp"

namespace {

namespace obs = scenario::observation;

TEST(ObservationLayout, ThePartsTileTheObservationInOrder) {
  int next = 0;
  for (const obs::Part& part : obs::kParts) {
    EXPECT_EQ(part.slice.start, next) << part.name;
    EXPECT_EQ(part.slice.size % part.item_size, 0) << part.name;
    next = part.slice.end();
  }
  EXPECT_EQ(next, scenario::PegTransferEnv::kObservationSize);
  EXPECT_EQ(obs::of(obs::kWrenches, raven::Arm::Right).start, 48);
  EXPECT_EQ(obs::item(obs::kRings, 5).end(), 72);
}

TEST(ObservationLayout, EachPartHoldsWhatItsNameSaysAfterTheArmsMoved) {
  scenario::PegTransferEnvOptions options;
  options.action = scenario::EnvAction::JointDeltas;
  scenario::PegTransferEnv env(options);
  env.reset(3);
  for (int i = 0; i < 20; ++i) env.step(env.expertAction());
  const Eigen::VectorXd& o = env.observation();
  twin::TwinPlatform& twin = env.twin();
  for (raven::Arm arm : raven::kArms) {
    const Eigen::VectorXd joints = o.segment<7>(obs::of(obs::kJoints, arm).start);
    EXPECT_EQ(joints, twin.measuredJs(arm).position);
    const Eigen::VectorXd pose = o.segment<7>(obs::of(obs::kToolPoses, arm).start);
    EXPECT_EQ(Eigen::Vector3d(pose.head<3>()), twin.measuredCp(arm).pose.translation());
    EXPECT_NEAR(pose.tail<4>().norm(), 1.0, 1e-12);
  }
  const scenario::PegLayout layout;
  for (std::size_t i = 0; i < layout.jobs.size(); ++i) {
    const Eigen::Vector3d centre = twin.world().softBody(layout.jobs[i].ring).centerOfMass();
    EXPECT_EQ(Eigen::Vector3d(o.segment<3>(obs::item(obs::kRings, i).start)), centre)
        << layout.jobs[i].ring;
  }
}

}  // namespace
