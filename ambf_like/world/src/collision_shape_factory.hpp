#pragma once
// Builds a body's Bullet collision shape (in its centre-of-mass frame) from its CollisionSpec.

#include <memory>
#include <vector>

#include "ambf_like/body_spec.hpp"
#include "ambf_like/mesh.hpp"

class btCollisionShape;
class btTriangleIndexVertexArray;

namespace ambf_like::detail {

/// Owns Bullet collision shapes and the vertex/index buffers that mesh shapes point into.
class ShapeStore {
 public:
  ShapeStore();
  ~ShapeStore();
  ShapeStore(const ShapeStore&) = delete;
  ShapeStore& operator=(const ShapeStore&) = delete;

  btCollisionShape* keep(std::unique_ptr<btCollisionShape> shape);
  /// A triangle-mesh view of `mesh` scaled by `scale`, moved by `transform`, kept alive here.
  btTriangleIndexVertexArray* meshInterface(const Mesh& mesh, double scale,
                                            const Transform& transform);

 private:
  struct Buffers;
  std::vector<std::unique_ptr<btCollisionShape>> shapes_;
  std::vector<std::unique_ptr<Buffers>> buffers_;
};

/// A body's collision shape and mass properties, in its centre-of-mass (COM) frame.
struct BodyShape {
  btCollisionShape* shape = nullptr;  ///< null when the body has no collision geometry
  /// What soft bodies meet instead of `shape`, when a static body's PLANE is a half-space in
  /// `shape` (see buildBodyShape); null otherwise.
  btCollisionShape* soft_proxy = nullptr;
  Transform com_in_body = Transform::Identity();
  Vec3 local_inertia = Vec3::Zero();
  std::size_t vertex_count = 0;     ///< collision mesh vertices
  std::size_t primitive_count = 0;  ///< collision primitives
};

/// A static body's PLANE is Bullet's half-space (btStaticPlaneShape, as AMBF makes it: contacts
/// with it are a vertex-plane test, where a box costs GJK per pair), and soft bodies, which
/// cannot rest on a half-space, meet a proxy with the plane as the top face of a 1 km box. A
/// moving body's PLANE is that box for everything.
BodyShape buildBodyShape(const BodySpec& body, MeshLibrary& meshes, ShapeStore& store);

}  // namespace ambf_like::detail
