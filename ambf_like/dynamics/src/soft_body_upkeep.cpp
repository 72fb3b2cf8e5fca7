#include "ambf_like/dynamics/soft_body_upkeep.hpp"

#include <BulletSoftBody/btSoftBody.h>

namespace ambf_like::detail {

namespace {

using Collision = btSoftBody::fCollision;

constexpr int kDeformableFaceModes = Collision::VF_DD | Collision::SDF_RDF | Collision::SDF_MDF;

/// Bullet's predictMotion builds and refits a face tree only for these bodies.
bool bulletKeepsFaceTree(const btSoftBody& body) {
  return (body.m_cfg.collisions & Collision::VF_SS) != 0 && body.m_faces.size() > 0;
}

}  // namespace

bool normalsAreRead(const btSoftBody& body) {
  const auto& cfg = body.m_cfg;
  return cfg.kLF > 0 || cfg.kDG > 0 || cfg.kPR != 0 || cfg.kVC > 0 ||
         (cfg.collisions & kDeformableFaceModes) != 0;
}

bool faceTreeIsRead(const btSoftBody& body, const btAlignedObjectArray<btSoftBody*>& world_bodies) {
  const int modes = body.m_cfg.collisions;
  if ((modes & kDeformableFaceModes) != 0) return true;
  for (int i = 0; i < world_bodies.size(); ++i) {
    const btSoftBody* other = world_bodies[i];
    if (other == &body) continue;
    // btSoftBody::defaultCollisionHandler(btSoftBody*) switches on the shared soft-soft modes.
    const int shared = modes & other->m_cfg.collisions & Collision::SVSmask;
    if (shared == Collision::VF_SS || shared == Collision::VF_DD) return true;
  }
  return false;
}

void rebuildReadableFaceTrees(const btAlignedObjectArray<btSoftBody*>& world_bodies) {
  for (int i = 0; i < world_bodies.size(); ++i) {
    btSoftBody& body = *world_bodies[i];
    // With m_bUpdateRtCst set, Bullet's prediction rebuilds the tree itself.
    const bool emptied = bulletKeepsFaceTree(body) && body.m_fdbvt.empty() && !body.m_bUpdateRtCst;
    if (emptied && faceTreeIsRead(body, world_bodies)) body.initializeFaceTree();
  }
}

void emptyUnreadFaceTrees(const btAlignedObjectArray<btSoftBody*>& world_bodies) {
  for (int i = 0; i < world_bodies.size(); ++i) {
    btSoftBody& body = *world_bodies[i];
    if (!body.m_fdbvt.empty() && bulletKeepsFaceTree(body) && !faceTreeIsRead(body, world_bodies)) {
      body.m_fdbvt.clear();
    }
  }
}

}  // namespace ambf_like::detail
