#pragma once
// The peg transfer as a trial: the six rings of raven_description's scene, each from its start
// post to the post behind it, watched for lifts, placements and drops; the trial starts each
// grasper jaws down over its half of the board, and a virtual participant follows PegArmGoals.

#include <memory>

#include "study/trial_task.hpp"

namespace study {

/// The peg-transfer task; an arm `arms` leaves out has no rings to move (its rings stay).
std::unique_ptr<TrialTask> makePegTransferTask(raven::PerArm<bool> arms);

}  // namespace study
