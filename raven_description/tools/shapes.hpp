#pragma once
// Geometry the model generator places on bodies: primitives for the simplified collision model,
// the same primitives tessellated for the dense variant, and generated meshes.

#include <Eigen/Geometry>
#include <array>
#include <filesystem>
#include <string>
#include <vector>

namespace raven::model {

/// A triangle mesh written to an OBJ file.
struct TriangleMesh {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<int, 3>> triangles;

  void append(const TriangleMesh& other, const Eigen::Isometry3d& pose);
  void writeObj(const std::filesystem::path& file, const std::string& comment) const;
};

/// A collision primitive on a body: a box (size = full extents), a capsule or a cylinder (size
/// = {radius, length, 0}) along the primitive's z axis, placed by `pose` in the body frame.
struct Primitive {
  enum class Type { Box, Capsule, Cylinder } type = Type::Box;
  Eigen::Vector3d size = Eigen::Vector3d::Zero();
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();

  double volume() const;
  /// A closed surface with about `segments` divisions around a round shape (boxes are divided
  /// into `segments` per edge), for the dense collision variant.
  TriangleMesh tessellate(int segments) const;
};

/// A capsule from `a` to `b` (body frame).
Primitive capsuleBetween(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double radius);
/// A cylinder from `a` to `b` (body frame).
Primitive cylinderBetween(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double radius);

/// One grasper jaw as a convex point set: a tapered, rounded blade of `length` along +x with its
/// gripping face on the y = 0 plane, on the side `side` (+1: y >= 0, -1: y <= 0).
std::vector<Eigen::Vector3d> jawHullPoints(double length, double width, double thickness, int side);

/// The convex hull surface of a point set (quickhull via Bullet's btConvexHullComputer).
TriangleMesh convexHull(const std::vector<Eigen::Vector3d>& points);

}  // namespace raven::model
