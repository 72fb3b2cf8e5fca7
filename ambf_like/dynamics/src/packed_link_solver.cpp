#include "ambf_like/dynamics/packed_link_solver.hpp"

#include <BulletSoftBody/btSoftBody.h>

namespace ambf_like::detail {

bool PackedLinkSolver::handles(const btSoftBody& body) {
  // Without these, the other position solvers (anchors, rigid and soft contacts) and the
  // clusters' impulses have nothing to do, so links are the whole position solve. Without
  // position iterations Bullet leaves the velocities alone, which solve() does not.
  return body.m_anchors.size() == 0 && body.m_rcontacts.size() == 0 &&
         body.m_scontacts.size() == 0 && body.m_clusters.size() == 0 &&
         body.m_cfg.viterations <= 0 && body.m_cfg.diterations <= 0 && body.m_cfg.piterations > 0;
}

void PackedLinkSolver::pack(const btSoftBody& body) {
  const btSoftBody::Node* first = &body.m_nodes[0];
  nodes_.resize(static_cast<std::size_t>(body.m_nodes.size()));
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    const btSoftBody::Node& n = first[i];
    nodes_[i] = {n.m_x.x(), n.m_x.y(), n.m_x.z(), n.m_im};
  }
  // Packed afresh every step: masses, stiffness, rest lengths and the links' order may all have
  // been changed since (one streaming pass, a small fraction of one iteration's cost).
  links_.clear();
  for (int i = 0; i < body.m_links.size(); ++i) {
    const btSoftBody::Link& l = body.m_links[i];
    if (l.m_c0 > 0) {
      links_.push_back(
          {static_cast<int>(l.m_n[0] - first), static_cast<int>(l.m_n[1] - first), l.m_c0, l.m_c1});
    }
  }
}

void PackedLinkSolver::solveLinksOnce() {
  // btSoftBody::PSolve_Links with kst = 1, written out per coordinate in Bullet's order of
  // operations (this file is built without floating-point contraction).
  for (const Link& l : links_) {
    Node& a = nodes_[static_cast<std::size_t>(l.a)];
    Node& b = nodes_[static_cast<std::size_t>(l.b)];
    const double dx = b.x - a.x;
    const double dy = b.y - a.y;
    const double dz = b.z - a.z;
    const double len = dx * dx + dy * dy + dz * dz;
    if (l.c1 + len > SIMD_EPSILON) {
      const double k = (l.c1 - len) / (l.c0 * (l.c1 + len));
      const double ka = k * a.inverse_mass;
      a.x -= dx * ka;
      a.y -= dy * ka;
      a.z -= dz * ka;
      const double kb = k * b.inverse_mass;
      b.x += dx * kb;
      b.y += dy * kb;
      b.z += dz * kb;
    }
  }
}

void PackedLinkSolver::solve(btSoftBody& body) {
  pack(body);
  const auto& sequence = body.m_cfg.m_psequence;
  for (int iteration = 0; iteration < body.m_cfg.piterations; ++iteration) {
    for (int s = 0; s < sequence.size(); ++s) {
      if (sequence[s] == btSoftBody::ePSolver::Linear) solveLinksOnce();
    }
  }
  // Bullet's end of the position solve: velocities from the moves, damped by kDP.
  const btScalar vc = body.m_sst.isdt * (1 - body.m_cfg.kDP);
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    btSoftBody::Node& n = body.m_nodes[static_cast<int>(i)];
    n.m_x.setValue(nodes_[i].x, nodes_[i].y, nodes_[i].z);
    n.m_v = (n.m_x - n.m_q) * vc;
    n.m_f = btVector3(0, 0, 0);
  }
}

}  // namespace ambf_like::detail
