#pragma once
// The statistics a within-subject study needs: descriptive values, the paired t-test with its
// effect size (Cohen's d_z), the exact Wilcoxon signed-rank test, Holm's correction for
// multiple comparisons, and the power of a paired t-test (noncentral t) with the number of
// participants a stated effect needs.

#include <vector>

namespace study {

double mean(const std::vector<double>& x);
/// Sample standard deviation (n - 1); NaN below two values.
double sd(const std::vector<double>& x);

/// A paired t-test of a - b.
struct PairedT {
  double t = 0.0;
  int df = 0;
  double p = 1.0;   ///< two-sided
  double dz = 0.0;  ///< mean difference / SD of the differences
};
/// Throws std::invalid_argument unless a and b have the same size, at least 2.
PairedT pairedT(const std::vector<double>& a, const std::vector<double>& b);

/// The Wilcoxon signed-rank test of a - b: exact two-sided p without ties (up to 30 pairs),
/// the normal approximation with the tie correction otherwise. Zero differences are dropped.
/// Also the matched-pairs rank-biserial correlation (W+ - W-) / (W+ + W-).
struct SignedRank {
  double w_plus = 0.0;
  double p = 1.0;
  double rank_biserial = 0.0;
  bool exact = true;
};
SignedRank wilcoxonSignedRank(const std::vector<double>& a, const std::vector<double>& b);

/// Holm's step-down adjustment of `p` (same order back).
std::vector<double> holm(const std::vector<double>& p);

/// The power of a two-sided paired t-test with `n` pairs for effect d_z at level `alpha`.
double pairedTPower(double dz, int n, double alpha);
/// The fewest pairs (2 or more) reaching `power`; -1 when more than `most` would be needed.
int pairsNeeded(double dz, double alpha, double power, int most = 10000);

}  // namespace study
