#pragma once
// Which of a soft body's derived data (its normals, its face tree) anything in the step reads.

#include <LinearMath/btAlignedObjectArray.h>

class btSoftBody;

namespace ambf_like::detail {

/// True when Bullet's step reads the normals btSoftBody::integrateMotion recomputes: aerodynamic
/// lift or drag (kLF, kDG), pressure (kPR), volume conservation (kVC), and the deformable
/// vertex-face and rigid-face contacts (VF_DD, SDF_RDF, SDF_MDF). Soft-rigid SDF contacts and
/// VF_SS soft-soft contacts compute their own normals; this project's code reads none.
bool normalsAreRead(const btSoftBody& body);

/// True when `body`'s face tree (m_fdbvt) can be read in the step: Bullet's collision dispatch
/// gives a pair of soft bodies vertex-face contacts (VF_SS or VF_DD, the modes that walk the other
/// body's face tree) when the modes they share are exactly one of those, and the deformable
/// modes walk the body's own faces. A ray test builds the tree itself when it finds it empty.
bool faceTreeIsRead(const btSoftBody& body, const btAlignedObjectArray<btSoftBody*>& world_bodies);

// Bullet builds and refits, every step, the face tree of each body with VF_SS in its collision
// flags, whether or not another body could collide with it (a quarter of AMBF's lone cloth's
// step). These two keep only the trees something can read.

/// Before btSoftBody::predictMotion: builds again each readable tree that was emptied (another
/// soft body has been added since), as Bullet builds it.
void rebuildReadableFaceTrees(const btAlignedObjectArray<btSoftBody*>& world_bodies);
/// After it (which built or refitted them): empties the trees nothing reads.
void emptyUnreadFaceTrees(const btAlignedObjectArray<btSoftBody*>& world_bodies);

}  // namespace ambf_like::detail
