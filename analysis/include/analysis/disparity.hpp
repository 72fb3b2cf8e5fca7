#pragma once
// Sim-vs-real disparity (../shared/reference/recordings.md): mean absolute joint differences
// between recordings, rows aligned by index, averaged over every pair of trials.

#include <span>
#include <string>
#include <vector>

#include "controller/recording_io.hpp"

namespace analysis {

/// Which rs columns a figure averages over.
struct JointGroup {
  std::string name;
  std::vector<int> jpos;  ///< indices into jpos0..15 (or jvel0..15)
  double scale = 1.0;     ///< to the reported unit (1000: metres -> mm)
  std::string unit;
};

/// Shoulder, elbow, wrist, jaw 1, jaw 2 of both arms (the roll is left out: the platforms' roll
/// zero differs by pi), in rad.
JointGroup revoluteJoints();
/// The insertion of both arms, in mm.
JointGroup prismaticJoints();

/// Joint positions (jpos) or velocities (jvel).
enum class Quantity { Position, Velocity };

/// Mean over rows (aligned by index, up to the shorter file) and over the group's joints of
/// |a - b|, in the group's unit. Throws controller::RecordingError if a column is missing.
double meanAbsoluteDifference(const controller::RsRecording& a, const controller::RsRecording& b,
                              const JointGroup& group, Quantity quantity = Quantity::Position);

/// The mean of meanAbsoluteDifference over every pair within `set` (T_SS, T_PP); NaN for fewer
/// than two files.
double withinSet(std::span<const controller::RsRecording> set, const JointGroup& group,
                 Quantity quantity = Quantity::Position);
/// The mean over every pair across the two sets (T_PS).
double acrossSets(std::span<const controller::RsRecording> a,
                  std::span<const controller::RsRecording> b, const JointGroup& group,
                  Quantity quantity = Quantity::Position);

}  // namespace analysis
