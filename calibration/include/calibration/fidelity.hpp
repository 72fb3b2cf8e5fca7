#pragma once
// How close a twin replay sits to the physical robot's replays, in the paper's summary figures:
// mean absolute joint-position (j_P) and joint-velocity (j_V) difference over the revolute joints
// and the insertion, rows aligned by index, no offsets removed.

#include <array>
#include <string>
#include <vector>

#include "analysis/trial_set.hpp"

namespace calibration {

/// The four summary figures, in the reported units (rad, mm, rad/s, mm/s).
struct Figures {
  double revolute_position = 0.0;
  double insertion_position = 0.0;
  double revolute_velocity = 0.0;
  double insertion_velocity = 0.0;

  std::array<double, 4> values() const {
    return {revolute_position, insertion_position, revolute_velocity, insertion_velocity};
  }
  static const std::array<std::string, 4>& names();  ///< "revolute j_P (rad)", ...
};

/// A set of physical trials as analysis sees them.
analysis::PlatformTrials physicalTrials(std::vector<analysis::Trial> trials);

/// T_PS of one twin trial against every physical trial; `remove_first_row`: each trial's
/// first-row value subtracted first.
Figures twinVsPhysical(const analysis::Trial& twin, const analysis::PlatformTrials& physical,
                       bool remove_first_row = false);
/// T_PP: the physical trials against each other (needs two or more).
Figures robotRepeatability(const analysis::PlatformTrials& physical, bool remove_first_row = false);

/// Per joint (analysis::recordedJoints order): mean absolute position and velocity difference.
struct JointFigures {
  std::vector<double> position, velocity;
};
JointFigures jointsTwinVsPhysical(const analysis::Trial& twin,
                                  const analysis::PlatformTrials& physical);
JointFigures jointsRepeatability(const analysis::PlatformTrials& physical);

}  // namespace calibration
