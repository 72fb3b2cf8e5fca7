#include "analysis/metrics.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

namespace analysis {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

const std::vector<JointRow>& rowsOf(const Trial& t, Quantity q) {
  return q == Quantity::Position ? t.position : t.velocity;
}

/// Calls `difference(d)` for every finite row difference of one column between two trials.
template <typename Sink>
void differences(const Trial& a, const Trial& b, Quantity q, std::size_t column,
                 bool remove_first_row, Sink difference) {
  const auto& ra = rowsOf(a, q);
  const auto& rb = rowsOf(b, q);
  const std::size_t rows = std::min(ra.size(), rb.size());
  if (rows == 0) return;
  const double offset = remove_first_row ? ra[0][column] - rb[0][column] : 0.0;
  for (std::size_t r = 0; r < rows; ++r) {
    const double d = ra[r][column] - rb[r][column] - offset;
    if (std::isfinite(d)) difference(d);
  }
}

}  // namespace

void forEachPair(const Comparison& c, const std::function<void(const Trial&, const Trial&)>& pair) {
  const auto& as = c.a->trials;
  const auto& bs = c.b->trials;
  for (std::size_t i = 0; i < as.size(); ++i) {
    for (std::size_t j = c.within() ? i + 1 : 0; j < bs.size(); ++j) pair(as[i], bs[j]);
  }
}

const char* quantityName(Quantity q) {
  return q == Quantity::Position ? "position" : "velocity";
}

const std::vector<JointInfo>& recordedJoints() {
  static const std::vector<JointInfo> joints = [] {
    const char* names[] = {"shoulder", "elbow", "insertion", nullptr,
                           "roll",     "wrist", "jaw 1",     "jaw 2"};
    std::vector<JointInfo> list;
    for (int arm = 0; arm < 2; ++arm) {
      for (int j = 0; j < 8; ++j) {
        if (!names[j]) continue;
        list.push_back({arm * 8 + j, std::string(arm == 0 ? "left " : "right ") + names[j],
                        j == 2 ? "m" : "rad"});
      }
    }
    return list;
  }();
  return joints;
}

JointGroup revoluteJoints() {
  return {"revolute", {0, 1, 5, 6, 7, 8, 9, 13, 14, 15}, 1.0, "rad"};
}

JointGroup prismaticJoints() {
  return {"prismatic", {2, 10}, 1000.0, "mm"};
}

std::string Comparison::symbol() const {
  const bool pa = a->profile.role == Role::Physical;
  const bool pb = b->profile.role == Role::Physical;
  return pa && pb ? "T_PP" : (pa || pb) ? "T_PS" : "T_SS";
}

std::string Comparison::describe() const {
  return within() ? a->profile.name + " vs " + a->profile.name
                  : a->profile.name + " vs " + b->profile.name;
}

std::vector<Comparison> comparisons(const TrialSet& set) {
  std::vector<Comparison> list;
  for (const auto& p : set.platforms) {
    if (p.trials.size() >= 2) list.push_back({&p, &p});
  }
  for (std::size_t i = 0; i < set.platforms.size(); ++i) {
    for (std::size_t j = i + 1; j < set.platforms.size(); ++j) {
      // Simulations first, so differences read "simulation minus physical".
      const auto* a = &set.platforms[i];
      const auto* b = &set.platforms[j];
      if (a->profile.role == Role::Physical && b->profile.role != Role::Physical) std::swap(a, b);
      list.push_back({a, b});
    }
  }
  return list;
}

DifferenceStats jointStats(const Comparison& c, Quantity q, int column, bool remove_first_row) {
  DifferenceStats stats;
  double sum_mean = 0.0, sum_square = 0.0;
  forEachPair(c, [&](const Trial& a, const Trial& b) {
    double abs_sum = 0.0, square_sum = 0.0;
    std::size_t n = 0;
    differences(a, b, q, static_cast<std::size_t>(column), remove_first_row, [&](double d) {
      abs_sum += std::abs(d);
      square_sum += d * d;
      stats.max = std::max(stats.max, std::abs(d));
      ++n;
    });
    if (n == 0) return;
    sum_mean += abs_sum / static_cast<double>(n);
    sum_square += square_sum / static_cast<double>(n);
    stats.samples += n;
    ++stats.pairs;
  });
  if (stats.pairs == 0) return {kNaN, kNaN, kNaN, 0, 0};
  stats.mean_abs = sum_mean / static_cast<double>(stats.pairs);
  stats.rms = std::sqrt(sum_square / static_cast<double>(stats.pairs));
  return stats;
}

double groupFigure(const Comparison& c, const JointGroup& group, Quantity q,
                   bool remove_first_row) {
  double sum = 0.0;
  int pairs = 0;
  forEachPair(c, [&](const Trial& a, const Trial& b) {
    double abs_sum = 0.0;
    std::size_t n = 0;
    for (int column : group.columns) {
      differences(a, b, q, static_cast<std::size_t>(column), remove_first_row, [&](double d) {
        abs_sum += std::abs(d);
        ++n;
      });
    }
    if (n == 0) return;
    sum += group.scale * abs_sum / static_cast<double>(n);
    ++pairs;
  });
  return pairs ? sum / pairs : kNaN;
}

double median(std::vector<double> values) {
  if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

}  // namespace analysis
