#pragma once
// Bullet's position-based solve of a soft body whose step has only its links to satisfy, run on
// packed copies of its nodes and links.

#include <BulletSoftBody/btSoftBody.h>

#include <unordered_map>
#include <vector>

namespace ambf_like::detail {

/// btSoftBody::solveConstraints for a body with no anchors, contacts or clusters and no velocity
/// or drift iterations (AMBF's cloth, for one): the position iterations over its links
/// (PSolve_Links), then the nodes' velocities from how far they moved. The same arithmetic in
/// the same order, so the same bits; what changes is the memory it walks. Bullet's node is some
/// 470 bytes and its link 112, so a 386-node cloth's 3,430 links touch half a megabyte per
/// iteration; packed, the nodes' positions fit the L1 cache (32 bytes each) and the links stream
/// past at 24 bytes each. A body's links are packed once and kept until Bullet refreshes their
/// constants (see forget) or its link array moves or changes size.
class PackedLinkSolver {
 public:
  /// True when solve(body) does all that body.solveConstraints() would in this step.
  static bool handles(const btSoftBody& body);
  /// Solves `body`'s step; `handles(body)` must hold.
  void solve(btSoftBody& body);
  /// Drops `body`'s packed links: called when their constants are about to be refreshed
  /// (m_bUpdateRtCst, which every change of mass, stiffness or rest length and every appended
  /// link sets), when the body leaves, and after a restore.
  void forget(const btSoftBody& body) { packed_.erase(&body); }
  void forgetAll() { packed_.clear(); }

 private:
  /// A node's position as a 4-lane vector (x, y, z, 0): one load, one store per update.
  using Position = double __attribute__((vector_size(32)));
  /// A link Bullet solves (m_c0 > 0): its nodes, (ima + imb) kLST and its rest length squared.
  struct Link {
    int a, b;
    double c0, c1;
  };
  /// One body's solved links, and the array they were packed from.
  struct PackedLinks {
    const btSoftBody::Link* from = nullptr;
    int count = 0;
    std::vector<Link> links;
  };
  const std::vector<Link>& pack(const btSoftBody& body);
  void solveLinksOnce(const std::vector<Link>& links);

  std::vector<Position> positions_;  ///< of the body being solved
  std::vector<double> inverse_masses_;
  std::unordered_map<const btSoftBody*, PackedLinks> packed_;
};

}  // namespace ambf_like::detail
