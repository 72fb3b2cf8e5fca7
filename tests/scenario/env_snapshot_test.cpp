// The learning environment's snapshots: after restoreState the same actions give the same
// observations and the expert the same actions, bit for bit, with the rings in the jaws; a state
// of another episode is refused.

#include <gtest/gtest.h>

#include "scenario/peg_transfer_env.hpp"

namespace {

scenario::PegTransferEnvOptions options() {
  scenario::PegTransferEnvOptions o;
  o.action = scenario::EnvAction::JointDeltas;
  o.randomize = true;
  return o;
}

/// `steps` steps of the expert's actions from where the environment is: the actions, and the
/// observations after them.
struct ExpertRun {
  std::vector<Eigen::VectorXd> actions, observations;
};

ExpertRun expertRun(scenario::PegTransferEnv& env, int steps) {
  ExpertRun run;
  for (int i = 0; i < steps; ++i) {
    run.actions.push_back(env.expertAction());
    run.observations.push_back(env.step(run.actions.back()).observation);
  }
  return run;
}

TEST(EnvSnapshot, TheSameActionsAfterARestoreGiveTheSameObservationsBitForBit) {
  scenario::PegTransferEnv env(options());
  const auto ring_z = [](const Eigen::VectorXd& o) {
    return o(scenario::observation::item(scenario::observation::kRings, 0).start + 2);
  };  // ring1's centre, z
  const double resting = ring_z(env.reset(4));
  int steps = 0;
  while (ring_z(env.observation()) < resting + 0.01 && ++steps < 1000) expertRun(env, 1);
  ASSERT_LT(steps, 1000) << "the expert lifts ring1";
  const auto state = env.saveState();  // ring1 held by friction between the jaws
  const Eigen::VectorXd saved = env.observation();
  const double saved_time = env.time();
  const ExpertRun first = expertRun(env, 150);  // carried over its target post
  expertRun(env, 100);

  env.restoreState(*state);
  EXPECT_EQ(env.time(), saved_time);
  EXPECT_EQ(env.observation(), saved);
  ExpertRun second;
  for (const auto& action : first.actions) {
    second.actions.push_back(env.expertAction());
    second.observations.push_back(env.step(action).observation);
  }
  EXPECT_EQ(second.observations, first.observations);
  EXPECT_EQ(second.actions, first.actions) << "the expert's progress came back with the world";
}

TEST(EnvSnapshot, AStateOfAnotherEpisodeIsRefused) {
  scenario::PegTransferEnv env(options());
  EXPECT_THROW(env.saveState(), std::logic_error);  // no episode yet
  env.reset(1);
  const auto state = env.saveState();
  env.reset(1);
  EXPECT_THROW(env.restoreState(*state), std::invalid_argument);
}

}  // namespace
