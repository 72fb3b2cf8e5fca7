#include "study/settings_tuner.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <boost/math/distributions/normal.hpp>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace study {

namespace {

/// The k-th point (k >= 1) of the Halton sequence in `dims` dimensions.
std::vector<double> halton(int k, std::size_t dims) {
  static constexpr int kPrimes[] = {2, 3, 5, 7, 11, 13};
  std::vector<double> out;
  for (std::size_t d = 0; d < dims; ++d) {
    const int base = kPrimes[d % 6];
    double f = 1.0, r = 0.0;
    for (int i = k; i > 0; i /= base) {
      f /= base;
      r += f * (i % base);
    }
    out.push_back(r);
  }
  return out;
}

/// A Gaussian process on the unit box with standardised outputs.
struct Process {
  Eigen::MatrixXd x;  ///< one point per row
  Eigen::VectorXd y;  ///< standardised: (cost - offset) / scale
  double offset = 0.0, scale = 1.0;
  double length = 0.3, noise = 0.1;
  Eigen::LLT<Eigen::MatrixXd> llt;
  Eigen::VectorXd alpha;

  double kernel(const Eigen::VectorXd& a, const Eigen::VectorXd& b) const {
    return std::exp(-0.5 * (a - b).squaredNorm() / (length * length));
  }
  /// Factors the kernel matrix; returns the log marginal likelihood.
  double fit() {
    const auto n = x.rows();
    Eigen::MatrixXd k(n, n);
    for (Eigen::Index i = 0; i < n; ++i) {
      for (Eigen::Index j = 0; j < n; ++j) k(i, j) = kernel(x.row(i), x.row(j));
    }
    k.diagonal().array() += noise;
    llt.compute(k);
    alpha = llt.solve(y);
    const Eigen::MatrixXd l = llt.matrixL();
    return -0.5 * y.dot(alpha) - l.diagonal().array().log().sum();
  }
  /// Mean and standard deviation at `p`.
  std::pair<double, double> predict(const Eigen::VectorXd& p) const {
    Eigen::VectorXd k(x.rows());
    for (Eigen::Index i = 0; i < x.rows(); ++i) k(i) = kernel(x.row(i), p);
    const double var = 1.0 - k.dot(llt.solve(k));
    return {k.dot(alpha), std::sqrt(std::max(var, 1e-12))};
  }
};

}  // namespace

SettingsTuner::SettingsTuner(std::vector<TunedParameter> parameters, int initial)
    : parameters_(std::move(parameters)), initial_(initial) {
  if (parameters_.empty()) throw std::invalid_argument("nothing to tune");
}

std::vector<double> SettingsTuner::fromBox(const std::vector<double>& u) const {
  std::vector<double> s;
  for (std::size_t i = 0; i < parameters_.size(); ++i) {
    s.push_back(parameters_[i].low + u[i] * (parameters_[i].high - parameters_[i].low));
  }
  return s;
}

namespace {

/// The process over `history` (in box units), its hyperparameters by marginal likelihood.
Process fitProcess(const std::vector<TunedParameter>& parameters,
                   const std::vector<TuningObservation>& history) {
  std::vector<std::vector<double>> box;
  std::vector<double> cost;
  for (const TuningObservation& o : history) {
    std::vector<double> u;
    for (std::size_t i = 0; i < parameters.size(); ++i) {
      u.push_back((o.settings.at(i) - parameters[i].low) /
                  (parameters[i].high - parameters[i].low));
    }
    box.push_back(u);
    cost.push_back(o.cost);
  }
  Process gp;
  const auto n = static_cast<Eigen::Index>(box.size());
  const auto dims = static_cast<Eigen::Index>(box.front().size());
  gp.x.resize(n, dims);
  gp.y.resize(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index d = 0; d < dims; ++d) {
      gp.x(i, d) = box[static_cast<std::size_t>(i)][static_cast<std::size_t>(d)];
    }
    gp.y(i) = cost[static_cast<std::size_t>(i)];
  }
  gp.offset = gp.y.mean();
  const double s =
      std::sqrt((gp.y.array() - gp.offset).square().sum() / std::max<double>(n - 1, 1));
  gp.scale = s > 0.0 ? s : 1.0;
  gp.y = (gp.y.array() - gp.offset) / gp.scale;
  double best = -std::numeric_limits<double>::infinity(), best_length = 0.3, best_noise = 0.1;
  for (double length : {0.1, 0.2, 0.3, 0.5, 0.8}) {
    for (double noise : {0.01, 0.05, 0.1, 0.3}) {
      gp.length = length;
      gp.noise = noise;
      const double evidence = gp.fit();
      if (evidence > best) {
        best = evidence;
        best_length = length;
        best_noise = noise;
      }
    }
  }
  gp.length = best_length;
  gp.noise = best_noise;
  gp.fit();
  return gp;
}

}  // namespace

std::vector<double> SettingsTuner::propose(const std::vector<TuningObservation>& history) const {
  const std::size_t dims = parameters_.size();
  if (static_cast<int>(history.size()) < initial_ || history.size() < 2) {
    return fromBox(halton(static_cast<int>(history.size()) + 1, dims));
  }
  const Process gp = fitProcess(parameters_, history);
  const double incumbent = gp.y.minCoeff();
  const boost::math::normal normal;
  double best_ei = -1.0;
  std::vector<double> best;
  for (int k = 1; k <= 2048; ++k) {
    const std::vector<double> u = halton(k + 97, dims);
    const auto [mu, sigma] =
        gp.predict(Eigen::Map<const Eigen::VectorXd>(u.data(), static_cast<Eigen::Index>(dims)));
    const double z = (incumbent - mu) / sigma;
    const double ei =
        (incumbent - mu) * boost::math::cdf(normal, z) + sigma * boost::math::pdf(normal, z);
    if (ei > best_ei) {
      best_ei = ei;
      best = u;
    }
  }
  return fromBox(best);
}

Recommendation SettingsTuner::recommend(const std::vector<TuningObservation>& history) const {
  if (history.empty()) throw std::invalid_argument("no tuning trials to recommend from");
  if (history.size() < 2) return {history.front().settings, history.front().cost};
  const Process gp = fitProcess(parameters_, history);
  Recommendation best{history.front().settings, std::numeric_limits<double>::infinity()};
  for (std::size_t i = 0; i < history.size(); ++i) {
    const double predicted =
        gp.offset + gp.scale * gp.predict(gp.x.row(static_cast<Eigen::Index>(i))).first;
    if (predicted < best.predicted_cost) best = {history[i].settings, predicted};
  }
  return best;
}

}  // namespace study
