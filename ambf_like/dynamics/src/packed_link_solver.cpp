#include "ambf_like/dynamics/packed_link_solver.hpp"

namespace ambf_like::detail {

bool PackedLinkSolver::handles(const btSoftBody& body) {
  // Without these, the other position solvers (anchors, rigid and soft contacts) and the
  // clusters' impulses have nothing to do, so links are the whole position solve. Without
  // position iterations Bullet leaves the velocities alone, which solve() does not.
  return body.m_anchors.size() == 0 && body.m_rcontacts.size() == 0 &&
         body.m_scontacts.size() == 0 && body.m_clusters.size() == 0 &&
         body.m_cfg.viterations <= 0 && body.m_cfg.diterations <= 0 && body.m_cfg.piterations > 0;
}

const std::vector<PackedLinkSolver::Link>& PackedLinkSolver::pack(const btSoftBody& body) {
  const btSoftBody::Node* first = &body.m_nodes[0];
  const auto count = static_cast<std::size_t>(body.m_nodes.size());
  positions_.resize(count);
  inverse_masses_.resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    const btSoftBody::Node& n = first[i];
    positions_[i] = Position{n.m_x.x(), n.m_x.y(), n.m_x.z(), 0.0};
    inverse_masses_[i] = n.m_im;
  }
  // The nodes' masses are read every step; the links' constants only change with Bullet's
  // refresh of them (forget), and their order with the array.
  PackedLinks& packed = packed_[&body];
  const btSoftBody::Link* from = body.m_links.size() > 0 ? &body.m_links[0] : nullptr;
  if (packed.from == from && packed.count == body.m_links.size()) return packed.links;
  packed = {from, body.m_links.size(), {}};
  for (int i = 0; i < body.m_links.size(); ++i) {
    const btSoftBody::Link& l = body.m_links[i];
    if (l.m_c0 > 0) {
      packed.links.push_back(
          {static_cast<int>(l.m_n[0] - first), static_cast<int>(l.m_n[1] - first), l.m_c0, l.m_c1});
    }
  }
  return packed.links;
}

void PackedLinkSolver::solveLinksOnce(const std::vector<Link>& links) {
  // btSoftBody::PSolve_Links with kst = 1 in Bullet's order of operations (this file is built
  // without floating-point contraction): lane by lane the same IEEE operations, so the same bits.
  // The fourth lane is 0 and stays 0.
  for (const Link& l : links) {
    const auto ia = static_cast<std::size_t>(l.a);
    const auto ib = static_cast<std::size_t>(l.b);
    const Position a = positions_[ia];
    const Position b = positions_[ib];
    const Position d = b - a;
    const Position d2 = d * d;
    const double len = d2[0] + d2[1] + d2[2];
    if (l.c1 + len > SIMD_EPSILON) {
      const double k = (l.c1 - len) / (l.c0 * (l.c1 + len));
      positions_[ia] = a - d * (k * inverse_masses_[ia]);
      positions_[ib] = b + d * (k * inverse_masses_[ib]);
    }
  }
}

void PackedLinkSolver::solve(btSoftBody& body) {
  const std::vector<Link>& links = pack(body);
  const auto& sequence = body.m_cfg.m_psequence;
  for (int iteration = 0; iteration < body.m_cfg.piterations; ++iteration) {
    for (int s = 0; s < sequence.size(); ++s) {
      if (sequence[s] == btSoftBody::ePSolver::Linear) solveLinksOnce(links);
    }
  }
  // Bullet's end of the position solve: velocities from the moves, damped by kDP.
  const btScalar vc = body.m_sst.isdt * (1 - body.m_cfg.kDP);
  for (std::size_t i = 0; i < positions_.size(); ++i) {
    btSoftBody::Node& n = body.m_nodes[static_cast<int>(i)];
    n.m_x.setValue(positions_[i][0], positions_[i][1], positions_[i][2]);
    n.m_v = (n.m_x - n.m_q) * vc;
    n.m_f = btVector3(0, 0, 0);
  }
}

}  // namespace ambf_like::detail
