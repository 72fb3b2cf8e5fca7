#pragma once
// Plain descriptions of collision and visual geometry, as written in a model file.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "ambf_like/transform.hpp"

namespace ambf_like {

enum class Axis { X, Y, Z };

enum class PrimitiveType { Box, Sphere, Cylinder, Capsule, Cone, Plane };

/// One primitive shape, with its dimensions and its pose in the owning body's frame.
struct PrimitiveShape {
  PrimitiveType type = PrimitiveType::Box;
  Vec3 box_size = Vec3::Zero();  ///< full extents along x, y, z (Box)
  double radius = 0.0;           ///< Sphere, Cylinder, Capsule, Cone
  double height = 0.0;           ///< Cylinder, Capsule (cylindrical part), Cone
  Axis axis = Axis::Z;           ///< long axis of Cylinder, Capsule, Cone
  Vec3 plane_normal = Vec3::UnitZ();
  double plane_offset = 0.0;
  /// Pose in the body frame; empty means AMBF's legacy rule: placed at the inertial offset.
  std::optional<Transform> offset;
};

enum class CollisionMeshType { ConcaveMesh, ConvexMesh, ConvexHull, PointCloud };

/// A body's collision geometry: a mesh file, a set of primitives, or nothing.
struct CollisionSpec {
  std::filesystem::path mesh;  ///< resolved path; empty when primitives (or nothing) are used
  CollisionMeshType mesh_type = CollisionMeshType::ConcaveMesh;
  std::vector<PrimitiveShape> primitives;
  double margin = 0.001;
  /// Bodies collide only if they share a group; empty means "collides with every group".
  std::vector<int> groups;

  bool empty() const { return mesh.empty() && primitives.empty(); }
};

}  // namespace ambf_like
