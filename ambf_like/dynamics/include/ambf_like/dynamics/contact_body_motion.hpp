#pragma once
// How an elastic body's contact impulses move the free rigid bodies they press on, within one
// solve of its contacts (two-way coupling).

#include <vector>

#include "ambf_like/dynamics/elastic_contacts.hpp"

namespace ambf_like::detail {

/// The velocity the contacts' impulses so far have given the bodies their surfaces belong to
/// (each body takes the opposite of what its contacts give their nodes), and how a contact's
/// surface answers an impulse.
class ContactBodyMotion {
 public:
  explicit ContactBodyMotion(const std::vector<ContactBody>& bodies);

  /// K: how much slower `at`'s surface point moves per unit impulse on `by`'s node (its body
  /// takes the opposite one), 1/m I - [r_at]x I^-1 [r_by]x; zero unless both are on one body.
  Eigen::Matrix3d response(const ElasticContact& at, const ElasticContact& by) const;
  /// `contact` with its surface moving as the other impulses leave it: its own impulse taken
  /// back out of its body's motion.
  ElasticContact seenBy(const ElasticContact& contact) const;
  /// Moves `contact`'s body (if any) by the opposite of `change`, a change of its impulse.
  void push(const ElasticContact& contact, const Eigen::Vector3d& change);

 private:
  /// How much the body's points at `arm` have sped up.
  Eigen::Vector3d pointChange(int body, const Eigen::Vector3d& arm) const;

  const std::vector<ContactBody>& bodies_;
  std::vector<Eigen::Vector3d> velocity_;  ///< of each body's centre of mass, gained so far
  std::vector<Eigen::Vector3d> spin_;      ///< of each body, gained so far
};

}  // namespace ambf_like::detail
