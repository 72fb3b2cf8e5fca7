#pragma once
// The paper's inconsistency figures (T_SS, T_PP, T_PS) per joint, for positions and velocities:
// mean absolute, RMS and maximum difference between trials aligned by row, averaged over every
// pair of trials, as recorded and after removing each trial's first-row value.

#include <functional>
#include <string>
#include <vector>

#include "analysis/trial_set.hpp"

namespace analysis {

enum class Quantity { Position, Velocity };
const char* quantityName(Quantity q);

/// One joint column's name ("left insertion"), unit ("m" or "rad") and whether it is used.
struct JointInfo {
  int column = 0;
  std::string name;
  std::string unit;
};
/// The 14 joint columns a Raven-II records (3 and 11 are unused).
const std::vector<JointInfo>& recordedJoints();

/// Which joints a summary figure averages over (../shared/reference/recordings.md).
struct JointGroup {
  std::string name;
  std::vector<int> columns;
  double scale = 1.0;  ///< to the reported unit (1000: m -> mm)
  std::string unit;
};
/// Shoulder, elbow, wrist, jaw 1, jaw 2 of both arms, rad (the roll is left out, as in the paper).
JointGroup revoluteJoints();
/// Both insertions, mm.
JointGroup prismaticJoints();

/// Two platforms compared (the same one twice: within-platform repeatability).
struct Comparison {
  const PlatformTrials* a = nullptr;
  const PlatformTrials* b = nullptr;
  bool within() const { return a == b; }
  /// T_SS, T_PP, T_PS (T_SS for two different simulators too).
  std::string symbol() const;
  std::string describe() const;  ///< "ambf vs physical"
};
/// Calls `pair(a, b)` for every trial pair of the comparison (each unordered pair once when a
/// platform is compared with itself).
void forEachPair(const Comparison& c, const std::function<void(const Trial&, const Trial&)>& pair);

/// Every platform with two or more trials against itself, then every pair of platforms.
std::vector<Comparison> comparisons(const TrialSet& set);

/// Differences between the trial pairs of a comparison.
struct DifferenceStats {
  double mean_abs = 0.0;
  double rms = 0.0;
  double max = 0.0;
  std::size_t pairs = 0;
  std::size_t samples = 0;  ///< finite row differences used, over all pairs
};

/// Per-pair statistics of column `column` averaged over the comparison's trial pairs (mean of
/// the pairs' mean absolute differences; root of the mean of their mean squares; the largest).
DifferenceStats jointStats(const Comparison& c, Quantity q, int column, bool remove_first_row);

/// The paper's summary figure: for every pair, the mean absolute difference over the group's
/// joints and rows (NaN skipped), in the group's unit, averaged over pairs. NaN without pairs.
double groupFigure(const Comparison& c, const JointGroup& group, Quantity q, bool remove_first_row);

/// The middle value (the mean of the two middle ones for an even count); NaN for none.
double median(std::vector<double> values);

}  // namespace analysis
