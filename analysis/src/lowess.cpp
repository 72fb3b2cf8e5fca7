#include "analysis/lowess.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

namespace analysis {

namespace {

/// The correlation of fewer than three points or of a constant series.
constexpr double kUndefined = std::numeric_limits<double>::quiet_NaN();

struct Points {
  std::vector<double> x, y;
};

/// The pairs where both values are finite, in their order.
Points finitePairs(const std::vector<double>& x, const std::vector<double>& y) {
  if (x.size() != y.size()) throw std::invalid_argument("x and y differ in length");
  Points p;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!std::isfinite(x[i]) || !std::isfinite(y[i])) continue;
    p.x.push_back(x[i]);
    p.y.push_back(y[i]);
  }
  return p;
}

/// The finite pairs, sorted by x.
Points finiteSorted(const std::vector<double>& x, const std::vector<double>& y) {
  const Points p = finitePairs(x, y);
  std::vector<std::size_t> order(p.x.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](auto a, auto b) { return p.x[a] < p.x[b]; });
  Points sorted;
  for (auto i : order) {
    sorted.x.push_back(p.x[i]);
    sorted.y.push_back(p.y[i]);
  }
  return sorted;
}

/// The weighted local line through the `k` points nearest x[i] (window [lo, lo + k)), at x[i].
double localFit(const Points& p, const std::vector<double>& robustness, std::size_t i,
                std::size_t lo, std::size_t k) {
  const double xi = p.x[i];
  const double h = std::max(xi - p.x[lo], p.x[lo + k - 1] - xi);
  double sw = 0.0, sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
  for (std::size_t j = lo; j < lo + k; ++j) {
    const double u = h > 0.0 ? std::abs(p.x[j] - xi) / (h * 1.0000001) : 0.0;
    const double tricube = u < 1.0 ? std::pow(1.0 - u * u * u, 3) : 0.0;
    const double w = tricube * robustness[j];
    sw += w;
    sx += w * p.x[j];
    sy += w * p.y[j];
    sxx += w * p.x[j] * p.x[j];
    sxy += w * p.x[j] * p.y[j];
  }
  if (sw <= 0.0) return p.y[i];
  const double mx = sx / sw, my = sy / sw;
  const double var = sxx / sw - mx * mx;
  const double range = p.x.back() - p.x.front();
  if (var <= 1e-12 * range * range) return my;  // all neighbours at one x: their mean
  const double slope = (sxy / sw - mx * my) / var;
  return my + slope * (xi - mx);
}

std::vector<double> ranks(const std::vector<double>& v) {
  std::vector<std::size_t> order(v.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](auto a, auto b) { return v[a] < v[b]; });
  std::vector<double> r(v.size());
  for (std::size_t i = 0; i < order.size();) {
    std::size_t j = i;
    while (j + 1 < order.size() && v[order[j + 1]] == v[order[i]]) ++j;
    const double mean_rank = 0.5 * static_cast<double>(i + j) + 1.0;
    for (std::size_t k = i; k <= j; ++k) r[order[k]] = mean_rank;
    i = j + 1;
  }
  return r;
}

}  // namespace

Curve lowess(const std::vector<double>& x, const std::vector<double>& y,
             const LowessOptions& options) {
  const Points p = finiteSorted(x, y);
  const std::size_t n = p.x.size();
  Curve curve;
  if (n == 0) return curve;
  const std::size_t k =
      std::clamp<std::size_t>(static_cast<std::size_t>(std::ceil(options.frac * n)), 2, n);
  const double delta = options.delta >= 0.0 ? options.delta : 0.01 * (p.x.back() - p.x.front());
  std::vector<double> robustness(n, 1.0), fitted(n, 0.0);
  for (int pass = 0; pass <= options.iterations; ++pass) {
    std::size_t lo = 0, last = 0;
    bool any = false;
    for (std::size_t i = 0; i < n; ++i) {
      if (any && p.x[i] - p.x[last] <= delta && i + 1 < n) continue;
      // Slide the window of k nearest neighbours along the sorted x.
      while (lo + k < n && p.x[i] - p.x[lo] > p.x[lo + k] - p.x[i]) ++lo;
      fitted[i] = localFit(p, robustness, i, lo, k);
      for (std::size_t j = any ? last + 1 : i; j < i; ++j) {  // interpolate the skipped points
        const double span = p.x[i] - p.x[last];
        const double w = span > 0.0 ? (p.x[j] - p.x[last]) / span : 0.0;
        fitted[j] = (1.0 - w) * fitted[last] + w * fitted[i];
      }
      last = i;
      any = true;
    }
    if (pass == options.iterations) break;
    std::vector<double> residual(n);
    for (std::size_t i = 0; i < n; ++i) residual[i] = std::abs(p.y[i] - fitted[i]);
    std::vector<double> sorted = residual;
    std::nth_element(sorted.begin(), sorted.begin() + n / 2, sorted.end());
    const double scale = 6.0 * sorted[n / 2];
    if (scale <= 0.0) break;  // a perfect fit: nothing to down-weight
    for (std::size_t i = 0; i < n; ++i) {
      const double u = residual[i] / scale;
      robustness[i] = u < 1.0 ? (1.0 - u * u) * (1.0 - u * u) : 0.0;
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (i > 0 && p.x[i] == p.x[i - 1]) continue;
    curve.x.push_back(p.x[i]);
    curve.y.push_back(fitted[i]);
  }
  return curve;
}

double pearson(const std::vector<double>& x, const std::vector<double>& y) {
  const Points p = finitePairs(x, y);
  const std::size_t n = p.x.size();
  if (n < 3) return kUndefined;
  const double mx = std::accumulate(p.x.begin(), p.x.end(), 0.0) / static_cast<double>(n);
  const double my = std::accumulate(p.y.begin(), p.y.end(), 0.0) / static_cast<double>(n);
  double sxy = 0.0, sxx = 0.0, syy = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    sxy += (p.x[i] - mx) * (p.y[i] - my);
    sxx += (p.x[i] - mx) * (p.x[i] - mx);
    syy += (p.y[i] - my) * (p.y[i] - my);
  }
  return sxx > 0.0 && syy > 0.0 ? sxy / std::sqrt(sxx * syy) : kUndefined;
}

double spearman(const std::vector<double>& x, const std::vector<double>& y) {
  const Points p = finitePairs(x, y);
  return pearson(ranks(p.x), ranks(p.y));
}

}  // namespace analysis
