#pragma once
// Builds a Bullet soft body from a mesh and the ADF soft-body config.

#include <memory>

#include "ambf_like/mesh.hpp"
#include "ambf_like/soft_body_spec.hpp"

class btSoftBody;
struct btSoftBodyWorldInfo;

namespace ambf_like::detail {

/// Nodes are the mesh vertices (placed at the spec's location and scale), links the triangle
/// edges, faces the triangles. Throws LoadError for a fixed-node index past the node count.
std::unique_ptr<btSoftBody> makeSoftBody(const SoftBodySpec& spec, const Mesh& mesh,
                                         btSoftBodyWorldInfo& world_info);

}  // namespace ambf_like::detail
