#pragma once
// Plain description of one rigid body as written in an ADF or URDF file.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "ambf_like/load_error.hpp"
#include "ambf_like/shape_spec.hpp"
#include "ambf_like/transform.hpp"

namespace ambf_like {

/// A dynamic body with nothing to compute its inertia from (no collision geometry, or its mesh
/// is missing) gets a uniform solid sphere's of its mass and this radius (m), with a warning.
inline constexpr double kFallbackInertiaRadius = 0.05;

/// Contact and damping properties of a rigid body (AMBF defaults).
struct SurfaceSpec {
  double static_friction = 0.5;
  double rolling_friction = 0.01;
  double restitution = 0.1;
  double linear_damping = 0.04;
  double angular_damping = 0.1;
};

/// A rigid body: geometry, mass properties, initial pose and surface.
struct BodySpec {
  std::string name;
  std::filesystem::path visual_mesh;  ///< resolved against the high resolution path
  std::vector<PrimitiveShape> visual_primitives;
  CollisionSpec collision;
  double mass = 0.0;                         ///< 0 makes the body static
  std::optional<Vec3> inertia;               ///< principal moments; empty: from the collision shape
  std::optional<Transform> inertial_offset;  ///< centre of mass frame in the body frame
  Transform location = Transform::Identity();  ///< body (mesh) frame in the world
  double scale = 1.0;
  SurfaceSpec surface;
  std::optional<Vec3> gravity;  ///< per-body override of the world/model gravity
  bool passive = false;
  bool visible = true;  ///< AMBF's `visible`: false hides the body from views; it still collides
  SourceRef where;
};

}  // namespace ambf_like
