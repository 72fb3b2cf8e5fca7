// The main job's operator asked to answer from the state alone (DAgger's expert): taken up from
// the state reached at every step, on the default twin, it still does the whole task.

#include <gtest/gtest.h>

#include "scenario/peg_transfer_env.hpp"

namespace {

TEST(ExpertFromState, TakenUpFromTheStateAtEveryStepTheOperatorPlacesAllSix) {
  scenario::PegTransferEnv env;  // the default: the motor-level twin, the nominal scene
  env.reset(57);
  scenario::PegTransferStep step;
  int steps = 0;
  while (!step.terminated && !step.truncated && ++steps < 20000) {
    step = env.step(env.expertAction(/*from_state=*/true));
  }
  EXPECT_TRUE(step.terminated) << "after " << steps << " steps, " << env.time() << " s";
  EXPECT_FALSE(step.faulted);
}

}  // namespace
