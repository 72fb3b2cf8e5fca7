#pragma once
// Locally weighted scatterplot smoothing (Cleveland 1979) and rank/linear correlation.

#include <vector>

namespace analysis {

/// A smoothed curve: y fitted at each sorted x.
struct Curve {
  std::vector<double> x;
  std::vector<double> y;
};

/// LOWESS options, named as in R's lowess() and statsmodels.
struct LowessOptions {
  double frac = 2.0 / 3.0;  ///< share of the points in each local fit
  int iterations = 3;       ///< robustifying passes (bisquare weights on the residuals)
  /// Points closer than this to the last fitted x are interpolated, not fitted; negative:
  /// 1 % of the x range (R's default).
  double delta = -1.0;
};

/// Fits y(x) with tricube-weighted local lines. Non-finite pairs are dropped; the curve has one
/// point per distinct remaining x. Throws std::invalid_argument if x and y differ in length.
Curve lowess(const std::vector<double>& x, const std::vector<double>& y,
             const LowessOptions& options = {});

/// Pearson's r over the finite pairs; NaN with fewer than 3 or no spread.
double pearson(const std::vector<double>& x, const std::vector<double>& y);
/// Spearman's rho (Pearson's r of the ranks, ties averaged).
double spearman(const std::vector<double>& x, const std::vector<double>& y);

}  // namespace analysis
