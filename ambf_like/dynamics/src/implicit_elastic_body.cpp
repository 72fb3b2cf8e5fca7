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

/// Projected Gauss-Seidel stops when no impulse changed by more than this (N s: 10 micronewtons
/// over a 1 ms step, a thousandth of a peg ring's weight; 1e-9 moved no force the tests read by
/// more than 1e-5 relative and took 1.6 times the sweeps over the main job), or after
/// kMostContactSweeps sweeps.
constexpr double kImpulseTolerance = 1e-8;
constexpr int kMostContactSweeps = 100;

/// Half the angle (rad) of the body's turn in a step above which the tetrahedra's rotations are
/// turned with it before they are followed: a tenth of what each of them is followed to.
constexpr double kTurnWorthFollowing = 0.5e-5;

/// The velocity that keeps `contact`'s node stuck to its surface, just reaching it.
Eigen::Vector3d stuckVelocity(const ElasticContact& contact) {
  const Eigen::Vector3d& n = contact.normal;
  const Eigen::Vector3d& u = contact.surface_velocity;
  return u - n * n.dot(u) + n * contact.least_normal_velocity;
}

/// The impulse that best keeps `contact` on its surface and inside its friction cone, given
/// the velocity `others` its node would have without it and `w`, its velocity per impulse.
Eigen::Vector3d contactImpulse(const ElasticContact& contact, const Eigen::Matrix3d& w,
                               const Eigen::Matrix3d& w_inverse, const Eigen::Vector3d& others) {
  const Eigen::Vector3d& n = contact.normal;
  const double shortfall = contact.least_normal_velocity - n.dot(others);
  if (shortfall <= 0.0) return Eigen::Vector3d::Zero();  // it leaves or rests unpressed
  // Stuck: it moves with the surface along it and just reaches it.
  const Eigen::Vector3d stuck = w_inverse * (stuckVelocity(contact) - others);
  const double normal = n.dot(stuck);
  const Eigen::Vector3d tangential = stuck - n * normal;
  const double slip_push = tangential.norm();
  if (normal > 0.0 && slip_push <= contact.friction * normal) return stuck;
  // Sliding: the friction impulse, mu times the normal one, against the slip.
  Eigen::Vector3d direction = n;
  if (slip_push > 0.0) direction += contact.friction * tangential / slip_push;
  double reach = n.dot(w * direction);
  if (!(reach > 0.0)) {
    direction = n;
    reach = n.dot(w * n);
  }
  return direction * std::max(0.0, shortfall / reach);
}

/// Replaces the impulses of the contacts that pressed in the last step by those that keep all of
/// them stuck, solved at once from their blocks of `w` (velocity per impulse, `slots` nodes),
/// when that is feasible: at a steady grasp it is the answer, and Gauss-Seidel then only
/// confirms it. Skipped when two of them share a node. `factored` keeps the last system solved:
/// the same nodes pressing give the same matrix (in the rest frame), so a steady grasp factors it
/// once.
void solveAsStuck(std::vector<ElasticContact>& contacts, const std::vector<std::size_t>& slot_of,
                  const std::vector<Eigen::Matrix3d>& w, std::size_t slots,
                  const std::vector<Eigen::Vector3d>& free_velocity, StuckSystem& factored) {
  std::vector<std::size_t> pressing;
  std::vector<bool> taken(slots, false);
  for (std::size_t c = 0; c < contacts.size(); ++c) {
    if (!(contacts[c].normal.dot(contacts[c].impulse) > 0.0)) continue;
    if (taken[slot_of[c]]) return;
    taken[slot_of[c]] = true;
    pressing.push_back(c);
  }
  if (pressing.empty()) return;
  const auto size = static_cast<Eigen::Index>(3 * pressing.size());
  std::vector<int> nodes;
  for (const std::size_t c : pressing) nodes.push_back(contacts[c].node);
  if (nodes != factored.nodes) {
    Eigen::MatrixXd response(size, size);
    for (std::size_t r = 0; r < pressing.size(); ++r) {
      for (std::size_t k = 0; k < pressing.size(); ++k) {
        response.block<3, 3>(static_cast<Eigen::Index>(3 * r), static_cast<Eigen::Index>(3 * k)) =
            w[slot_of[pressing[r]] * slots + slot_of[pressing[k]]];
      }
    }
    factored.nodes = std::move(nodes);
    factored.factor.compute(response);
  }
  if (factored.factor.info() != Eigen::Success) return;
  Eigen::VectorXd wanted(size);
  for (std::size_t r = 0; r < pressing.size(); ++r) {
    // The other contacts' impulses are zero: they did not press.
    wanted.segment<3>(static_cast<Eigen::Index>(3 * r)) =
        stuckVelocity(contacts[pressing[r]]) - free_velocity[slot_of[pressing[r]]];
  }
  const Eigen::VectorXd impulse = factored.factor.solve(wanted);
  // Taken only if every one of them presses and stays inside its cone: then it is the answer
  // for them. Otherwise (a resting body's supports can pull against each other when all are held
  // stuck) Gauss-Seidel starts from the last step's impulses.
  for (std::size_t r = 0; r < pressing.size(); ++r) {
    const ElasticContact& contact = contacts[pressing[r]];
    const Eigen::Vector3d p = impulse.segment<3>(static_cast<Eigen::Index>(3 * r));
    const double normal = contact.normal.dot(p);
    if (!(normal > 0.0) || (p - contact.normal * normal).norm() > contact.friction * normal) {
      return;
    }
  }
  for (std::size_t c = 0; c < contacts.size(); ++c) {
    if (!taken[slot_of[c]]) contacts[c].impulse.setZero();
  }
  for (std::size_t r = 0; r < pressing.size(); ++r) {
    contacts[pressing[r]].impulse = impulse.segment<3>(static_cast<Eigen::Index>(3 * r));
  }
}

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
  const double total = node_mass.sum();
  if (total > 0.0) {
    const Eigen::Vector3d rest_centre = rest * node_mass.transpose() / total;
    weighted_rest_ = (rest.colwise() - rest_centre) * node_mass.asDiagonal();
  }
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
  blocks_.nodes.clear();
  stuck_.nodes.clear();
}

const ImplicitElasticBody::Response& ImplicitElasticBody::responseTo(int node) {
  auto it = responses_.find(node);
  if (it != responses_.end()) return it->second;
  const auto size = mass_.size();
  Response response = Response::Zero(size, 3);
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

void ImplicitElasticBody::step(btSoftBody& body, double h,
                               const std::vector<btVector3>& acceleration,
                               std::vector<ElasticContact>& contacts) {
  if (h != factored_step_) factor(h);
  const int count = body.m_nodes.size();
  Eigen::VectorXd position(3 * count), velocity(3 * count);
  for (int i = 0; i < count; ++i) {
    position.segment<3>(3 * i) = toEigen(body.m_nodes[i].m_x);
    velocity.segment<3>(3 * i) = toEigen(body.m_nodes[i].m_v);
  }
  const Eigen::Quaterniond body_before = body_rotation_.quaternion;
  followBodyRotation(position);
  const Eigen::Quaterniond body_turn = body_rotation_.quaternion * body_before.conjugate();
  if (body_turn.vec().squaredNorm() > kTurnWorthFollowing * kTurnWorthFollowing) {
    tets_.turnRotations(body_turn);
  }
  Eigen::VectorXd load = Eigen::VectorXd::Zero(3 * count);
  tets_.addForces(position, load);
  for (int i = 0; i < count; ++i) {
    const double mass = mass_(3 * i);
    load.segment<3>(3 * i) =
        mass > 0.0
            ? Eigen::Vector3d(mass * velocity.segment<3>(3 * i) +
                              h * (load.segment<3>(3 * i) +
                                   mass * toEigen(acceleration[static_cast<std::size_t>(i)])))
            : Eigen::Vector3d::Zero();
  }
  // Solved, contacts too, in the rest frame, where the matrix was factored.
  const Eigen::Matrix3d& turn = body_rotation_.matrix;
  turnEach(load, turn.transpose());
  Eigen::VectorXd& next = load;
  system_.solveInPlace(next);
  for (auto& c : contacts) turnContact(c, turn.transpose());
  solveContacts(next, contacts);
  std::unordered_map<int, Eigen::Vector3d> pushed;
  for (const auto& c : contacts) {
    pushed.try_emplace(c.node, Eigen::Vector3d::Zero()).first->second += c.impulse;
  }
  for (const auto& [node, impulse] : pushed) next.noalias() += responseTo(node) * impulse;
  for (auto& c : contacts) turnContact(c, turn);
  turnEach(next, turn);
  position += h * next;
  // A node that began inside a surface was moved out: that is not motion it keeps.
  for (const auto& c : contacts) {
    if (c.start_depth <= 0.0) continue;
    auto v = next.segment<3>(3 * c.node);
    const double outward = c.normal.dot(v - c.surface_velocity);
    v -= c.normal * std::clamp(c.start_depth / h, 0.0, std::max(0.0, outward));
  }
  for (int i = 0; i < count; ++i) {
    btSoftBody::Node& node = body.m_nodes[i];
    node.m_q = node.m_x;
    node.m_x = toBt(position.segment<3>(3 * i));
    node.m_v = toBt(next.segment<3>(3 * i));
  }
}

void ImplicitElasticBody::solveContacts(const Eigen::VectorXd& free_velocity,
                                        std::vector<ElasticContact>& contacts) {
  if (contacts.empty()) return;
  std::vector<int> nodes;
  std::vector<std::size_t> slot_of(contacts.size());
  for (std::size_t c = 0; c < contacts.size(); ++c) {
    const auto found = std::find(nodes.begin(), nodes.end(), contacts[c].node);
    slot_of[c] = static_cast<std::size_t>(found - nodes.begin());
    if (found == nodes.end()) nodes.push_back(contacts[c].node);
  }
  const std::size_t slots = nodes.size();
  if (nodes != blocks_.nodes) {
    blocks_.w.resize(slots * slots);
    for (std::size_t i = 0; i < slots; ++i) {
      const Response& response = responseTo(nodes[i]);
      for (std::size_t j = 0; j < slots; ++j) {
        blocks_.w[j * slots + i] = response.middleRows<3>(3 * nodes[j]);
      }
    }
    blocks_.w_inverse.resize(slots);
    for (std::size_t i = 0; i < slots; ++i) {
      blocks_.w_inverse[i] = blocks_.w[i * slots + i].inverse();
    }
    blocks_.nodes = std::move(nodes);
  }
  const std::vector<Eigen::Matrix3d>& w = blocks_.w;
  const std::vector<Eigen::Matrix3d>& w_inverse = blocks_.w_inverse;
  const std::vector<int>& contact_nodes = blocks_.nodes;
  std::vector<Eigen::Vector3d> velocity(slots);
  for (std::size_t j = 0; j < slots; ++j) {
    velocity[j] = free_velocity.segment<3>(3 * contact_nodes[j]);
  }
  solveAsStuck(contacts, slot_of, w, slots, velocity, stuck_);
  for (std::size_t j = 0; j < slots; ++j) {
    for (std::size_t c = 0; c < contacts.size(); ++c) {
      velocity[j] += w[j * slots + slot_of[c]] * contacts[c].impulse;
    }
  }
  for (int sweep = 0; sweep < kMostContactSweeps; ++sweep) {
    double largest_change = 0.0;
    for (std::size_t c = 0; c < contacts.size(); ++c) {
      ElasticContact& contact = contacts[c];
      const std::size_t i = slot_of[c];
      const Eigen::Matrix3d& own = w[i * slots + i];
      const Eigen::Vector3d others = velocity[i] - own * contact.impulse;
      const Eigen::Vector3d change =
          contactImpulse(contact, own, w_inverse[i], others) - contact.impulse;
      if (change.isZero(0.0)) continue;
      for (std::size_t j = 0; j < slots; ++j) velocity[j] += w[j * slots + i] * change;
      contact.impulse += change;
      largest_change = std::max(largest_change, change.norm());
    }
    if (largest_change <= kImpulseTolerance) break;
  }
}

}  // namespace ambf_like::detail
