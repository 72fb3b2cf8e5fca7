#include "ambf_like/dynamics/contact_body_motion.hpp"

namespace ambf_like::detail {

namespace {

/// [v]x: the matrix that takes the cross product v x u.
Eigen::Matrix3d crossMatrix(const Eigen::Vector3d& v) {
  Eigen::Matrix3d m;
  m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return m;
}

}  // namespace

ContactBodyMotion::ContactBodyMotion(const std::vector<ContactBody>& bodies)
    : bodies_(bodies),
      velocity_(bodies.size(), Eigen::Vector3d::Zero()),
      spin_(bodies.size(), Eigen::Vector3d::Zero()) {}

Eigen::Matrix3d ContactBodyMotion::response(const ElasticContact& at,
                                            const ElasticContact& by) const {
  if (at.body < 0 || at.body != by.body) return Eigen::Matrix3d::Zero();
  const ContactBody& body = bodies_[static_cast<std::size_t>(at.body)];
  return body.inverse_mass * Eigen::Matrix3d::Identity() -
         crossMatrix(at.arm) * body.inverse_inertia * crossMatrix(by.arm);
}

ElasticContact ContactBodyMotion::seenBy(const ElasticContact& contact) const {
  if (contact.body < 0) return contact;
  const Eigen::Vector3d change =
      pointChange(contact.body, contact.arm) + response(contact, contact) * contact.impulse;
  ElasticContact seen = contact;
  seen.surface_velocity += change;
  seen.least_normal_velocity += contact.normal.dot(change);
  return seen;
}

void ContactBodyMotion::push(const ElasticContact& contact, const Eigen::Vector3d& change) {
  if (contact.body < 0) return;
  const auto b = static_cast<std::size_t>(contact.body);
  velocity_[b] -= bodies_[b].inverse_mass * change;
  spin_[b] -= bodies_[b].inverse_inertia * contact.arm.cross(change);
}

Eigen::Vector3d ContactBodyMotion::pointChange(int body, const Eigen::Vector3d& arm) const {
  const auto b = static_cast<std::size_t>(body);
  return velocity_[b] + spin_[b].cross(arm);
}

}  // namespace ambf_like::detail
