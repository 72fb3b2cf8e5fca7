#include "scenario/ring_nodes.hpp"

#include <BulletSoftBody/btSoftBody.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace scenario {

RingNodes inspect(const ambf_like::SoftBody& ring) {
  RingNodes s;
  const btSoftBody& body = ring.bullet();
  s.bottom = std::numeric_limits<double>::infinity();
  for (int i = 0; i < body.m_nodes.size(); ++i) {
    const auto& n = body.m_nodes[i];
    const Eigen::Vector3d p(n.m_x.x(), n.m_x.y(), n.m_x.z());
    s.finite = s.finite && p.allFinite() && std::isfinite(n.m_v.length());
    s.centre += p;
    s.bottom = std::min(s.bottom, p.z());
    s.speed = std::max(s.speed, static_cast<double>(n.m_v.length()));
  }
  s.centre /= std::max(1, body.m_nodes.size());
  return s;
}

}  // namespace scenario
