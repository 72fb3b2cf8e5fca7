#pragma once
// The rows of one-sided limits: when they join the solve, and what they ask of it.

#include <BulletDynamics/ConstraintSolver/btContactSolverInfo.h>
#include <BulletDynamics/Featherstone/btMultiBodyConstraint.h>
#include <BulletDynamics/Featherstone/btMultiBodySolverConstraint.h>

namespace ambf_like::detail {

/// How near a bound (rad or m), beyond two steps of travel, a limit is put into the world. Each
/// engaged limit costs the solver's set-up and island work every step even while its bound is
/// far (its rows are made only within kLimitRowBand).
inline constexpr double kLimitWatchBand = 1e-3;

/// Besides the step's own travel, how near its bound (rad or m) a limit gets a row.
inline constexpr double kLimitRowBand = 1e-4;

/// Whether a limit `gap` (rad or m) from its bound, closing or opening at `rate`, is within two
/// steps of `dt` at that rate and `band` of it: kLimitWatchBand to be in the world,
/// kLimitRowBand to get a row this step.
bool withinReach(double gap, double rate, double dt, double band);

/// Appends row `index` of `owner` (a limit within one multibody) to `rows`, its normals zero: the
/// multibody solver works from its Jacobians, which fillMultiBodyConstraint then sets.
btMultiBodySolverConstraint& openLimitRow(btMultiBodyConstraintArray& rows,
                                          btMultiBodyConstraint& owner, int index);

/// Aims a rigid one-sided row whose coordinate is `gap` from its bound (< 0: past it) and
/// changes at `closing` (what fillMultiBodyConstraint returned). Apart, the coordinate may close
/// by the gap in this step and no more, so it reaches the bound and stops there instead of
/// passing it by up to a step's travel (Bullet's joint limits make their rows only once past).
/// Past it, it stops and the error is pushed out at the solver's error-reduction rate, a deep
/// one (beyond the split threshold) as a separate push when the solver splits impulses, as
/// Bullet's contacts and limits do.
void aimLimitRow(btMultiBodySolverConstraint& row, double closing, double gap,
                 const btContactSolverInfo& info);

}  // namespace ambf_like::detail
