#pragma once
// Bullet's position-based solve of a soft body whose step has only its links to satisfy, run on
// packed copies of its nodes and links.

#include <vector>

class btSoftBody;

namespace ambf_like::detail {

/// btSoftBody::solveConstraints for a body with no anchors, contacts or clusters and no velocity
/// or drift iterations (AMBF's cloth, for one): the position iterations over its links
/// (PSolve_Links), then the nodes' velocities from how far they moved. The same arithmetic in
/// the same order, so the same bits; what changes is the memory it walks. Bullet's node is some
/// 470 bytes and its link 112, so a 386-node cloth's 3,430 links touch half a megabyte per
/// iteration; packed, the nodes' positions fit the L1 cache (32 bytes each) and the links stream
/// past at 24 bytes each.
class PackedLinkSolver {
 public:
  /// True when solve(body) does all that body.solveConstraints() would in this step.
  static bool handles(const btSoftBody& body);
  /// Solves `body`'s step; `handles(body)` must hold.
  void solve(btSoftBody& body);

 private:
  /// A node's position as a 4-lane vector (x, y, z, 0): one load, one store per update.
  using Position = double __attribute__((vector_size(32)));
  /// A link Bullet solves (m_c0 > 0): its nodes, (ima + imb) kLST and its rest length squared.
  struct Link {
    int a, b;
    double c0, c1;
  };
  void pack(const btSoftBody& body);
  void solveLinksOnce();

  std::vector<Position> positions_;
  std::vector<double> inverse_masses_;
  std::vector<Link> links_;
};

}  // namespace ambf_like::detail
