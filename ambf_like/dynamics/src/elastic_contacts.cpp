#include "ambf_like/dynamics/elastic_contacts.hpp"

#include <Eigen/LU>
#include <algorithm>

namespace ambf_like::detail {

namespace {

/// Projected Gauss-Seidel stops when no impulse changed by more than this (N s: 10 micronewtons
/// over a 1 ms step, a thousandth of a ring's weight; 1e-9 moved no force the tests read by
/// more than 1e-5 relative and took 1.6 times the sweeps over the main job), or after
/// kMostContactSweeps sweeps.
constexpr double kImpulseTolerance = 1e-8;
constexpr int kMostContactSweeps = 100;

/// The velocity that keeps `contact`'s node stuck to its surface, just reaching it, or on its pin.
Eigen::Vector3d stuckVelocity(const ElasticContact& contact) {
  if (contact.pinned) return contact.surface_velocity;
  const Eigen::Vector3d& n = contact.normal;
  const Eigen::Vector3d& u = contact.surface_velocity;
  return u - n * n.dot(u) + n * contact.least_normal_velocity;
}

/// The impulse that best keeps `contact` on its surface and inside its friction cone (or on its
/// pin), given the velocity `others` its node would have without it and `w`, its velocity per
/// impulse.
Eigen::Vector3d contactImpulse(const ElasticContact& contact, const Eigen::Matrix3d& w,
                               const Eigen::Matrix3d& w_inverse, const Eigen::Vector3d& others) {
  if (contact.pinned) return w_inverse * (stuckVelocity(contact) - others);
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

/// Whether `impulse` pushes `contact`'s node off its surface inside its cone, or is none, give
/// or take `slack` (N s: Gauss-Seidel leaves slides on the cone's edge).
bool withinCone(const ElasticContact& contact, const Eigen::Vector3d& impulse, double slack) {
  const double normal = contact.normal.dot(impulse);
  const double tangential = (impulse - contact.normal * normal).norm();
  return normal >= -slack && tangential <= contact.friction * std::max(0.0, normal) + slack;
}

/// Whether `impulse` is one `contact` can give: any, for a pin; pressing and inside its cone
/// for a contact.
bool admissible(const ElasticContact& contact, const Eigen::Vector3d& impulse) {
  return contact.pinned || (contact.normal.dot(impulse) > 0.0 && withinCone(contact, impulse, 0.0));
}

/// Takes out of two contacts of one node the part of their impulses that only passes through
/// it, from one surface to the other, keeping their sum (the node's own impulse): all of it on
/// the one whose cone holds it when one does; else, along the axis between their normals, as
/// much as keeps both inside their cones.
void releasePinch(ElasticContact& a, ElasticContact& b) {
  const Eigen::Vector3d node = a.impulse + b.impulse;
  const double slack = 1e-9 * (a.impulse.norm() + b.impulse.norm());
  const bool on_a = withinCone(a, node, slack);
  if (on_a || withinCone(b, node, slack)) {
    const bool a_takes =
        on_a && (!withinCone(b, node, slack) || a.normal.dot(node) >= b.normal.dot(node));
    (a_takes ? a : b).impulse = node;
    (a_takes ? b : a).impulse.setZero();
    return;
  }
  const Eigen::Vector3d axis = (a.normal - b.normal).normalized();
  const double through = std::min(axis.dot(a.impulse), -axis.dot(b.impulse));
  if (!(through > 0.0)) return;
  const auto fits = [&](double t) {
    return withinCone(a, a.impulse - t * axis, slack) && withinCone(b, b.impulse + t * axis, slack);
  };
  if (!fits(0.0)) return;
  double low = 0.0;  // the cones are convex: what fits is an interval from 0
  double high = through;
  if (!fits(high)) {
    for (int halving = 0; halving < 40; ++halving) {
      const double mid = 0.5 * (low + high);
      (fits(mid) ? low : high) = mid;
    }
    high = low;
  }
  a.impulse -= high * axis;
  b.impulse += high * axis;
}

/// The contacts, two by two, of one node on surfaces that face each other (a node that can be
/// caught between them).
std::vector<ContactPair> facingPairs(const std::vector<ElasticContact>& contacts) {
  std::vector<ContactPair> pairs;
  for (std::size_t a = 0; a < contacts.size(); ++a) {
    if (contacts[a].pinned) continue;
    for (std::size_t b = a + 1; b < contacts.size(); ++b) {
      if (contacts[b].node == contacts[a].node && !contacts[b].pinned &&
          contacts[a].normal.dot(contacts[b].normal) < 0.0) {
        pairs.emplace_back(a, b);
      }
    }
  }
  return pairs;
}

}  // namespace

void ElasticContactSolver::forget() {
  blocks_.nodes.clear();
  stuck_.nodes.clear();
}

void ElasticContactSolver::solve(const Eigen::VectorXd& free_velocity,
                                 std::vector<ElasticContact>& contacts,
                                 const ResponseOf& response) {
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
      const NodeResponse& column = response(nodes[i]);
      for (std::size_t j = 0; j < slots; ++j) {
        blocks_.w[j * slots + i] = column.middleRows<3>(3 * nodes[j]);
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
  std::vector<Eigen::Vector3d> velocity(slots);
  for (std::size_t j = 0; j < slots; ++j) {
    velocity[j] = free_velocity.segment<3>(3 * blocks_.nodes[j]);
  }
  solveAsStuck(contacts, slot_of, velocity);
  for (std::size_t j = 0; j < slots; ++j) {
    for (std::size_t c = 0; c < contacts.size(); ++c) {
      velocity[j] += w[j * slots + slot_of[c]] * contacts[c].impulse;
    }
  }
  const std::vector<ContactPair> pinches = facingPairs(contacts);
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
    releasePinches(contacts, slot_of, pinches, velocity);
    if (largest_change <= kImpulseTolerance) break;
  }
}

/// A node caught between two surfaces that face each other (a ring's node between closing jaws,
/// or between a jaw and the board) cannot meet both once they are closer than it allows:
/// Gauss-Seidel then grows the two contacts' impulses against each other, sweep after sweep and,
/// warm started, step after step, and each surface is pushed with all of it while the node
/// feels only their difference. A node of zero thickness carries no load from one rigid surface
/// to the other (the jaws' meeting is their own stop's, a jaw on the board their rigid
/// contact's), so that part is taken out after every sweep. Caught between a fixed surface and
/// a moving one, the node stays on the fixed one, as the moving one will be stopped by it.
void ElasticContactSolver::releasePinches(std::vector<ElasticContact>& contacts,
                                          const std::vector<std::size_t>& slot_of,
                                          const std::vector<ContactPair>& pinches,
                                          std::vector<Eigen::Vector3d>& velocity) const {
  const std::size_t slots = blocks_.nodes.size();
  for (const auto& [a, b] : pinches) {
    if (contacts[a].fixed_surface == contacts[b].fixed_surface) {
      releasePinch(contacts[a], contacts[b]);
      continue;
    }
    ElasticContact& fixed = contacts[a].fixed_surface ? contacts[a] : contacts[b];
    ElasticContact& moving = contacts[a].fixed_surface ? contacts[b] : contacts[a];
    const std::size_t i = slot_of[a];
    const Eigen::Matrix3d& own = blocks_.w[i * slots + i];
    const Eigen::Vector3d before = fixed.impulse + moving.impulse;
    moving.impulse.setZero();
    fixed.impulse = contactImpulse(fixed, own, blocks_.w_inverse[i], velocity[i] - own * before);
    const Eigen::Vector3d change = fixed.impulse - before;
    for (std::size_t j = 0; j < slots; ++j) velocity[j] += blocks_.w[j * slots + i] * change;
  }
}

/// Replaces the impulses of the contacts that pressed in the last solve, and of the pins, by
/// those that keep all of them stuck, solved at once from their blocks of the inverse, when that
/// is feasible: at a steady grasp it is the answer, and Gauss-Seidel then only confirms it.
/// Skipped when two of them share a node. The same nodes pressing give the same matrix (in the
/// rest frame), so a steady grasp factors it once.
void ElasticContactSolver::solveAsStuck(std::vector<ElasticContact>& contacts,
                                        const std::vector<std::size_t>& slot_of,
                                        const std::vector<Eigen::Vector3d>& free_velocity) {
  const std::size_t slots = blocks_.nodes.size();
  std::vector<std::size_t> pressing;
  std::vector<bool> taken(slots, false);
  for (std::size_t c = 0; c < contacts.size(); ++c) {
    if (!contacts[c].pinned && !(contacts[c].normal.dot(contacts[c].impulse) > 0.0)) continue;
    if (taken[slot_of[c]]) return;
    taken[slot_of[c]] = true;
    pressing.push_back(c);
  }
  if (pressing.empty()) return;
  const auto size = static_cast<Eigen::Index>(3 * pressing.size());
  std::vector<int> nodes;
  for (const std::size_t c : pressing) nodes.push_back(contacts[c].node);
  if (nodes != stuck_.nodes) {
    Eigen::MatrixXd response(size, size);
    for (std::size_t r = 0; r < pressing.size(); ++r) {
      for (std::size_t k = 0; k < pressing.size(); ++k) {
        response.block<3, 3>(static_cast<Eigen::Index>(3 * r), static_cast<Eigen::Index>(3 * k)) =
            blocks_.w[slot_of[pressing[r]] * slots + slot_of[pressing[k]]];
      }
    }
    stuck_.nodes = std::move(nodes);
    stuck_.factor.compute(response);
  }
  if (stuck_.factor.info() != Eigen::Success) return;
  Eigen::VectorXd wanted(size);
  for (std::size_t r = 0; r < pressing.size(); ++r) {
    // The other contacts' impulses are zero: they did not press.
    wanted.segment<3>(static_cast<Eigen::Index>(3 * r)) =
        stuckVelocity(contacts[pressing[r]]) - free_velocity[slot_of[pressing[r]]];
  }
  const Eigen::VectorXd impulse = stuck_.factor.solve(wanted);
  // Taken only if every one of them can give its impulse: then it is the answer for them.
  // Otherwise (a resting body's supports can pull against each other when all are held stuck)
  // Gauss-Seidel starts from the last impulses.
  for (std::size_t r = 0; r < pressing.size(); ++r) {
    if (!admissible(contacts[pressing[r]], impulse.segment<3>(static_cast<Eigen::Index>(3 * r)))) {
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

}  // namespace ambf_like::detail
