#pragma once
// Triangles of primitive shapes and of Bullet collision shapes, for drawing.

#include "ambf_like/shape_spec.hpp"
#include "viewer/scene_geometry.hpp"

class btCollisionShape;

namespace viewer::detail {

/// A primitive (box, sphere, cylinder, capsule, cone; a plane as a 2 m square) centred on its
/// own frame, `scale` applied to its dimensions.
TriangleMesh tessellate(const ambf_like::PrimitiveShape& shape, double scale);

/// A Bullet collision shape in its own frame: primitives as above, convex shapes as their hull,
/// concave meshes triangle by triangle, compounds child by child.
TriangleMesh tessellate(const btCollisionShape& shape);

}  // namespace viewer::detail
