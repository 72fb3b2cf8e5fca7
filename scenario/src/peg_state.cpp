#include "scenario/peg_state.hpp"

#include <BulletSoftBody/btSoftBody.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace scenario {

PegState inspect(const ambf_like::SoftBody& peg) {
  PegState s;
  const btSoftBody& body = peg.bullet();
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
  // The divergence theorem over the closed surface: sum of signed tetrahedra to the origin.
  for (int f = 0; f < body.m_faces.size(); ++f) {
    const auto& face = body.m_faces[f];
    s.volume += face.m_n[0]->m_x.dot(face.m_n[1]->m_x.cross(face.m_n[2]->m_x)) / 6.0;
  }
  s.volume = std::abs(s.volume);
  return s;
}

double bearingGap(const ambf_like::SoftBody& peg, const Eigen::Vector2d& axis) {
  const btSoftBody& body = peg.bullet();
  std::vector<double> bearings;
  bearings.reserve(static_cast<std::size_t>(body.m_nodes.size()));
  for (int i = 0; i < body.m_nodes.size(); ++i) {
    const btVector3& p = body.m_nodes[i].m_x;
    bearings.push_back(std::atan2(p.y() - axis.y(), p.x() - axis.x()));
  }
  if (bearings.empty()) return 2.0 * M_PI;
  std::sort(bearings.begin(), bearings.end());
  double gap = bearings.front() + 2.0 * M_PI - bearings.back();
  for (std::size_t i = 1; i < bearings.size(); ++i)
    gap = std::max(gap, bearings[i] - bearings[i - 1]);
  return gap;
}

bool restsOn(const ambf_like::SoftBody& peg, const Eigen::Vector2d& post, const PegGeometry& g,
             double tolerance) {
  const PegState s = inspect(peg);
  return s.finite && s.bottom < g.board_top + tolerance && bearingGap(peg, post) < M_PI / 2.0;
}

}  // namespace scenario
