#include "study/statistics.hpp"

#include <algorithm>
#include <boost/math/distributions/non_central_t.hpp>
#include <boost/math/distributions/normal.hpp>
#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

#include "not_measured.hpp"

namespace study {

namespace {

std::vector<double> differences(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size() || a.size() < 2) {
    throw std::invalid_argument("a paired test needs two samples of the same size, at least 2");
  }
  std::vector<double> d;
  for (std::size_t i = 0; i < a.size(); ++i) d.push_back(a[i] - b[i]);
  return d;
}

}  // namespace

double mean(const std::vector<double>& x) {
  if (x.empty()) return kNotMeasured;
  return std::accumulate(x.begin(), x.end(), 0.0) / static_cast<double>(x.size());
}

double sd(const std::vector<double>& x) {
  if (x.size() < 2) return kNotMeasured;
  const double m = mean(x);
  double ss = 0.0;
  for (double v : x) ss += (v - m) * (v - m);
  return std::sqrt(ss / static_cast<double>(x.size() - 1));
}

PairedT pairedT(const std::vector<double>& a, const std::vector<double>& b) {
  const std::vector<double> d = differences(a, b);
  PairedT r;
  r.df = static_cast<int>(d.size()) - 1;
  const double m = mean(d), s = sd(d);
  if (s == 0.0) {  // every difference the same: no spread to test against
    r.t = m == 0.0 ? 0.0 : std::copysign(std::numeric_limits<double>::infinity(), m);
    r.p = m == 0.0 ? 1.0 : 0.0;
    r.dz = r.t;
    return r;
  }
  r.dz = m / s;
  r.t = r.dz * std::sqrt(static_cast<double>(d.size()));
  const boost::math::students_t dist(r.df);
  r.p = std::min(1.0, 2.0 * boost::math::cdf(boost::math::complement(dist, std::abs(r.t))));
  return r;
}

SignedRank wilcoxonSignedRank(const std::vector<double>& a, const std::vector<double>& b) {
  std::vector<double> d;
  for (double v : differences(a, b)) {
    if (v != 0.0) d.push_back(v);
  }
  SignedRank r;
  const std::size_t n = d.size();
  if (n == 0) return r;
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](std::size_t i, std::size_t j) { return std::abs(d[i]) < std::abs(d[j]); });
  std::vector<double> rank(n);
  bool ties = false;
  double tie_term = 0.0;  // sum of t^3 - t over tie groups
  for (std::size_t i = 0; i < n;) {
    std::size_t j = i;
    while (j + 1 < n && std::abs(d[order[j + 1]]) == std::abs(d[order[i]])) ++j;
    const double average = 0.5 * static_cast<double>(i + j) + 1.0;
    for (std::size_t k = i; k <= j; ++k) rank[order[k]] = average;
    const auto t = static_cast<double>(j - i + 1);
    if (t > 1.0) ties = true;
    tie_term += t * t * t - t;
    i = j + 1;
  }
  double w_minus = 0.0;
  for (std::size_t i = 0; i < n; ++i) (d[i] > 0.0 ? r.w_plus : w_minus) += rank[i];
  const double total = r.w_plus + w_minus;
  r.rank_biserial = (r.w_plus - w_minus) / total;
  r.exact = !ties && n <= 30;
  if (r.exact) {
    // The number of sign patterns giving each rank sum 0..n(n+1)/2.
    const std::size_t top = n * (n + 1) / 2;
    std::vector<double> ways(top + 1, 0.0);
    ways[0] = 1.0;
    for (std::size_t k = 1; k <= n; ++k) {
      for (std::size_t s = top; s >= k; --s) ways[s] += ways[s - k];
    }
    const double all = std::pow(2.0, static_cast<double>(n));
    const auto w = static_cast<std::size_t>(std::lround(std::min(r.w_plus, w_minus)));
    double tail = 0.0;
    for (std::size_t s = 0; s <= w; ++s) tail += ways[s];
    r.p = std::min(1.0, 2.0 * tail / all);
    return r;
  }
  const double nn = static_cast<double>(n);
  const double mu = nn * (nn + 1.0) / 4.0;
  const double sigma = std::sqrt(nn * (nn + 1.0) * (2.0 * nn + 1.0) / 24.0 - tie_term / 48.0);
  const double z = (std::abs(r.w_plus - mu) - 0.5) / sigma;  // continuity correction
  const boost::math::normal normal;
  r.p = std::min(1.0, 2.0 * boost::math::cdf(boost::math::complement(normal, std::max(z, 0.0))));
  return r;
}

std::vector<double> holm(const std::vector<double>& p) {
  const std::size_t m = p.size();
  std::vector<std::size_t> order(m);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) { return p[i] < p[j]; });
  std::vector<double> adjusted(m);
  double running = 0.0;
  for (std::size_t k = 0; k < m; ++k) {
    running = std::max(running, std::min(1.0, static_cast<double>(m - k) * p[order[k]]));
    adjusted[order[k]] = running;
  }
  return adjusted;
}

double pairedTPower(double dz, int n, double alpha) {
  if (n < 2) return 0.0;
  const double df = n - 1;
  const double critical =
      boost::math::quantile(boost::math::complement(boost::math::students_t(df), alpha / 2.0));
  const double shift = std::abs(dz) * std::sqrt(static_cast<double>(n));
  if (shift == 0.0) return alpha;
  const boost::math::non_central_t dist(df, shift);
  return boost::math::cdf(boost::math::complement(dist, critical)) +
         boost::math::cdf(dist, -critical);
}

int pairsNeeded(double dz, double alpha, double power, int most) {
  if (!(std::abs(dz) > 0.0)) return -1;
  for (int n = 2; n <= most; ++n) {
    if (pairedTPower(dz, n, alpha) >= power) return n;
  }
  return -1;
}

}  // namespace study
