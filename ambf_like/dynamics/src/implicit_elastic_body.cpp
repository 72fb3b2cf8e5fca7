#include "ambf_like/dynamics/implicit_elastic_body.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "ambf_like/bullet_conversions.hpp"

namespace ambf_like::detail {

namespace {

/// Turns every node's 3-vector of `nodes` (3 entries per node) by `turn`.
void turnEach(Eigen::VectorXd& nodes, const Eigen::Matrix3d& turn) {
  Eigen::Map<Eigen::Matrix3Xd> each(nodes.data(), 3, nodes.size() / 3);
  each = turn * each;
}

/// Turns a contact's normal, surface velocity and impulse by `turn`.
void turnContact(ElasticContact& contact, const Eigen::Matrix3d& turn) {
  contact.normal = turn * contact.normal;
  contact.surface_velocity = turn * contact.surface_velocity;
  contact.impulse = turn * contact.impulse;
}

/// Half the angle (rad) of the body's turn in a step above which the tetrahedra's rotations are
/// turned with it before they are followed: a tenth of what each of them is followed to.
constexpr double kTurnWorthFollowing = 0.5e-5;

/// Iterations of one step, at most; the iteration also stops when a whole iteration moves no
/// node by more than kStillShare of the mean rest edge.
constexpr int kMostIterations = 40;
constexpr double kStillShare = 1e-5;
/// The energy a step may gain beyond the work put in: this share of the kinetic energy it moves
/// (before and after). The elastic energy stays out of it: a body resting under a load stores
/// energy that no step moves, and a share of that let a resting beam swing by a micron for good.
constexpr double kEnergyTolerance = 1e-6;
/// What the elastic energy's reading resolves: its rotations are followed to 1e-4 rad, an error
/// of the order of 1e-8 of it. A step gaining less than that is not reported as gaining.
constexpr double kElasticReading = 1e-8;
/// Halvings of one iteration's step, at most, and Armijo's share of the promised decrease.
constexpr int kMostHalvings = 12;
constexpr double kArmijoShare = 1e-4;
/// The relative rounding of the incremental potential, within which a cut-back step is taken as
/// not increasing it.
constexpr double kRounding = 1e-12;

}  // namespace

ImplicitElasticBody::ImplicitElasticBody(const btSoftBody& body, const SoftMaterial& material)
    : tets_(body, material) {
  const int count = body.m_nodes.size();
  mass_.resize(3 * count);
  Eigen::Matrix3Xd rest(3, count);
  Eigen::RowVectorXd node_mass(count);
  for (int i = 0; i < count; ++i) {
    const btSoftBody::Node& node = body.m_nodes[i];
    node_mass(i) = node.m_im > 0.0 ? 1.0 / node.m_im : 0.0;
    mass_.segment<3>(3 * i).setConstant(node_mass(i));
    rest.col(i) = toEigen(node.m_x);
  }
  moves_ = (mass_.array() > 0.0).cast<double>().matrix();
  const double total = node_mass.sum();
  if (total > 0.0) {
    const Eigen::Vector3d rest_centre = rest * node_mass.transpose() / total;
    weighted_rest_ = (rest.colwise() - rest_centre) * node_mass.asDiagonal();
  }
  double edges = 0.0;
  for (int t = 0; t < body.m_tetras.size(); ++t) {
    const btSoftBody::Tetra& tet = body.m_tetras[t];
    for (int a = 0; a < 4; ++a) {
      for (int b = a + 1; b < 4; ++b) edges += (tet.m_n[a]->m_x - tet.m_n[b]->m_x).length();
    }
  }
  if (body.m_tetras.size() > 0) mean_edge_ = edges / (6.0 * body.m_tetras.size());
}

void ImplicitElasticBody::factor(double h) {
  const auto size = mass_.size();
  std::vector<Eigen::Triplet<double>> entries;
  for (const auto& k : tets_.restStiffness()) {
    // A node that stays put keeps only its diagonal: its velocity is zero.
    if (mass_(k.row()) > 0.0 && mass_(k.col()) > 0.0) {
      entries.emplace_back(k.row(), k.col(), h * h * k.value());
    }
  }
  for (Eigen::Index i = 0; i < size; ++i) {
    entries.emplace_back(i, i, mass_(i) > 0.0 ? mass_(i) : 1.0);
  }
  Eigen::SparseMatrix<double> system(size, size);
  system.setFromTriplets(entries.begin(), entries.end());
  if (!system_.compute(system)) {
    throw std::runtime_error("a soft body's implicit elastic system could not be factored");
  }
  factored_step_ = h;
  responses_.clear();
  contact_solver_.forget();
}

const NodeResponse& ImplicitElasticBody::responseTo(int node) {
  auto it = responses_.find(node);
  if (it != responses_.end()) return it->second;
  const auto size = mass_.size();
  NodeResponse response = NodeResponse::Zero(size, 3);
  for (int k = 0; k < 3; ++k) {
    response(3 * node + k, k) = 1.0;
    system_.solveInPlace(response.col(k));
  }
  return responses_.emplace(node, std::move(response)).first->second;
}

void ImplicitElasticBody::followBodyRotation(const Eigen::VectorXd& positions) {
  if (weighted_rest_.size() == 0) return;  // no node moves
  // sum_i m_i (x_i - c)(r_i - r_c)^T, and sum_i m_i (r_i - r_c) = 0 takes c out of it.
  const Eigen::Map<const Eigen::Matrix3Xd> x(positions.data(), 3, weighted_rest_.cols());
  const Eigen::Matrix3d spread = x * weighted_rest_.transpose();
  followRotation(spread, body_rotation_);
}

void ImplicitElasticBody::evaluate(Elastic& at) {
  const Eigen::Quaterniond body_before = body_rotation_.quaternion;
  followBodyRotation(at.positions);
  const Eigen::Quaterniond body_turn = body_rotation_.quaternion * body_before.conjugate();
  if (body_turn.vec().squaredNorm() > kTurnWorthFollowing * kTurnWorthFollowing) {
    tets_.turnRotations(body_turn);
  }
  at.forces.setZero(at.positions.size());
  at.energy = tets_.addForces(at.positions, at.forces);
}

void ImplicitElasticBody::solveFrom(const Eigen::VectorXd& velocity, bool from_rest,
                                    const Eigen::VectorXd& residual,
                                    std::vector<ElasticContact>& contacts,
                                    Eigen::VectorXd& direction) {
  // Solved, contacts too, in the rest frame, where the matrix was factored: the free velocity
  // v + A^-1 r, then the impulses that keep the contacts and pins.
  const Eigen::Matrix3d& turn = body_rotation_.matrix;
  direction = residual;
  turnEach(direction, turn.transpose());
  system_.solveInPlace(direction);
  free_velocity_ = direction;
  if (!from_rest) {
    Eigen::Map<Eigen::Matrix3Xd>(free_velocity_.data(), 3, free_velocity_.size() / 3).noalias() +=
        turn.transpose() *
        Eigen::Map<const Eigen::Matrix3Xd>(velocity.data(), 3, velocity.size() / 3);
  }
  for (auto& c : contacts) turnContact(c, turn.transpose());
  contact_solver_.solve(free_velocity_, contacts,
                        [this](int node) -> const NodeResponse& { return responseTo(node); });
  pushed_.clear();
  for (const auto& c : contacts) {
    pushed_.try_emplace(c.node, Eigen::Vector3d::Zero()).first->second += c.impulse;
  }
  for (const auto& [node, impulse] : pushed_) direction.noalias() += responseTo(node) * impulse;
  for (auto& c : contacts) turnContact(c, turn);
  turnEach(direction, turn);
}

ElasticStepReport ImplicitElasticBody::step(btSoftBody& body, double h,
                                            const std::vector<btVector3>& acceleration,
                                            std::vector<ElasticContact>& contacts) {
  if (h != factored_step_) factor(h);
  const int count = body.m_nodes.size();
  loadNodes(body, acceleration);
  const Eigen::VectorXd& start = start_;
  const Eigen::VectorXd& start_velocity = start_velocity_;
  const Eigen::VectorXd& weight = weight_;
  const auto kinetic = [&](const Eigen::VectorXd& v) { return 0.5 * v.dot(mass_.cwiseProduct(v)); };
  const auto contactWork = [&](const Eigen::VectorXd& v) {
    double work = 0.0;
    for (const auto& c : contacts) work += c.impulse.dot(v.segment<3>(3 * c.node));
    return work;
  };
  // The incremental potential with the contacts' impulses as fixed forces.
  const auto potential = [&](const Eigen::VectorXd& v, const Elastic& at) {
    return kinetic(v - start_velocity) - h * weight.dot(v) + at.energy - contactWork(v);
  };
  const double start_kinetic = kinetic(start_velocity);
  const double start_elastic = last_.energy;
  const double energy_before = start_kinetic + start_elastic - weight.dot(start);  // gravity's
  ElasticStepReport report;
  Eigen::VectorXd& velocity = velocity_;
  Eigen::VectorXd& direction = direction_;
  velocity.setZero(3 * count);
  const Elastic& at = last_;  // where the iteration stands (trial_ the points it tries)
  // Whether the iterate `v`, with `trial_`'s forces, gains no energy beyond the work put in; in
  // `report`, whether it gains none that the step resolves: the elastic energy's reading, and the
  // work of the forces over the distance the iteration calls still.
  const auto keepsEnergy = [&](const Eigen::VectorXd& v) {
    const double energy_after = kinetic(v) + trial_.energy - weight.dot(trial_.positions);
    const double gain = energy_after - energy_before - contactWork(v);  // beyond the work put in
    const double allowed = kEnergyTolerance * (start_kinetic + kinetic(v));
    report.energy_kept = gain <= allowed;
    if (!report.energy_kept) {  // summed over the nodes only when it decides something
      const double unresolved =
          kElasticReading * (start_elastic + trial_.energy) +
          kStillShare * mean_edge_ * (trial_.forces + weight).cwiseProduct(moves_).lpNorm<1>();
      report.energy_kept = gain <= allowed + unresolved;
    }
    return gain <= allowed;
  };
  const auto tryStep = [&](double share) {
    trial_.positions = start + h * (velocity + share * direction);
    evaluate(trial_);
  };
  for (;;) {
    residual_ = (mass_.cwiseProduct(start_velocity - velocity) + h * (at.forces + weight))
                    .cwiseProduct(moves_);
    solveFrom(velocity, report.iterations == 0, residual_, contacts, direction);
    ++report.iterations;
    tryStep(1.0);
    double share = 1.0;
    if (!keepsEnergy(velocity + direction)) {
      // Cut back until Phi falls by a share of what the solve promised (A d = residual +
      // impulses, so the promise is d^T A d), read to within its rounding.
      const double promised = direction.dot(residual_) + contactWork(direction);
      const double from = potential(velocity, at);
      const double rounding = kRounding * (std::abs(from) + start_kinetic);
      for (int halving = 0; halving < kMostHalvings; ++halving) {
        if (potential(velocity + share * direction, trial_) <=
            from - kArmijoShare * share * promised + rounding) {
          break;
        }
        share *= 0.5;
        ++report.halvings;
        tryStep(share);
      }
      keepsEnergy(velocity + share * direction);
    }
    velocity += share * direction;
    std::swap(last_, trial_);
    const double moved = share * h * direction.lpNorm<Eigen::Infinity>();
    if (report.energy_kept || report.iterations == kMostIterations ||
        moved <= kStillShare * mean_edge_) {
      break;
    }
  }
  storeNodes(body, h, contacts, velocity);
  return report;
}

void ImplicitElasticBody::loadNodes(const btSoftBody& body,
                                    const std::vector<btVector3>& acceleration) {
  const int count = body.m_nodes.size();
  start_.resize(3 * count);
  start_velocity_.resize(3 * count);
  weight_.resize(3 * count);
  for (int i = 0; i < count; ++i) {
    start_.segment<3>(3 * i) = toEigen(body.m_nodes[i].m_x);
    start_velocity_.segment<3>(3 * i) = toEigen(body.m_nodes[i].m_v);
    weight_.segment<3>(3 * i) = mass_(3 * i) * toEigen(acceleration[static_cast<std::size_t>(i)]);
  }
  // The last step ended where this one starts unless something moved the nodes since.
  if (last_.positions.size() != start_.size() || last_.positions != start_) {
    last_.positions = start_;
    evaluate(last_);
  }
}

void ImplicitElasticBody::storeNodes(btSoftBody& body, double h,
                                     const std::vector<ElasticContact>& contacts,
                                     Eigen::VectorXd& velocity) const {
  // A node that began inside a surface was moved out: that is not motion it keeps.
  for (const auto& c : contacts) {
    if (c.pinned || c.start_depth <= 0.0) continue;
    auto v = velocity.segment<3>(3 * c.node);
    const double outward = c.normal.dot(v - c.surface_velocity);
    v -= c.normal * std::clamp(c.start_depth / h, 0.0, std::max(0.0, outward));
  }
  for (int i = 0; i < body.m_nodes.size(); ++i) {
    btSoftBody::Node& node = body.m_nodes[i];
    node.m_q = node.m_x;
    node.m_x = toBt(last_.positions.segment<3>(3 * i));
    node.m_v = toBt(velocity.segment<3>(3 * i));
  }
}

}  // namespace ambf_like::detail
