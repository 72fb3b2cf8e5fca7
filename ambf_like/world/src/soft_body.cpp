#include "ambf_like/soft_body.hpp"

#include <BulletSoftBody/btSoftBody.h>

#include "ambf_like/bullet_conversions.hpp"

namespace ambf_like {

SoftBody::SoftBody(SoftBodySpec spec, std::string qualified_name, std::unique_ptr<btSoftBody> body)
    : spec_(std::move(spec)), qualified_name_(std::move(qualified_name)), body_(std::move(body)) {}

SoftBody::~SoftBody() = default;

std::size_t SoftBody::nodeCount() const {
  return static_cast<std::size_t>(body_->m_nodes.size());
}

Vec3 SoftBody::nodePosition(std::size_t index) const {
  return toEigen(body_->m_nodes[static_cast<int>(index)].m_x);
}

std::vector<Vec3> SoftBody::nodePositions() const {
  std::vector<Vec3> out;
  out.reserve(nodeCount());
  for (int i = 0; i < body_->m_nodes.size(); ++i) out.push_back(toEigen(body_->m_nodes[i].m_x));
  return out;
}

Vec3 SoftBody::centerOfMass() const {
  return toEigen(body_->getCenterOfMass());
}

bool SoftBody::isFinite() const {
  // A body asleep has not moved since it fell asleep, which a body that is not finite never does.
  if (isAsleep()) return true;
  for (int i = 0; i < body_->m_nodes.size(); ++i) {
    const auto& node = body_->m_nodes[i];
    if (!toEigen(node.m_x).allFinite() || !toEigen(node.m_v).allFinite()) return false;
  }
  return true;
}

bool SoftBody::isAsleep() const {
  return body_->getActivationState() == DISABLE_SIMULATION;
}

}  // namespace ambf_like
