#pragma once
// A model being generated: bodies at their reference poses with their geometry, and the joints
// between them, before it is written out as an ADF file.

#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <vector>

#include "shapes.hpp"

namespace raven::model {

/// A rigid body: its pose in the world at the reference configuration and its geometry.
struct BodyDraft {
  std::string name{};
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  double mass = 0.0;
  /// Smallest principal inertia (kg m^2): the reflected inertia of a cable-driven joint's motor,
  /// which dwarfs a small link's own (and keeps Bullet's solver well conditioned).
  double armature = 0.0;
  std::vector<Primitive> primitives{};  ///< simplified collision (and visual) geometry
  std::vector<Eigen::Vector3d> hull{};  ///< or a convex hull point set (the jaws)
  std::string hull_mesh{};              ///< file name for the hull mesh
  double friction = 0.0;                ///< ADF `friction: {static}`; 0: AMBF's default
  /// Centre of mass in the body frame when known (the robot's own); else the geometry's.
  std::optional<Eigen::Vector3d> centre_of_mass{};
};

/// A joint between two drafted bodies, in ADF terms.
struct JointDraft {
  std::string name, parent, child;
  bool prismatic = false;
  Eigen::Vector3d parent_axis, parent_pivot, child_axis, child_pivot;
  double offset = 0.0;  ///< ADF `offset`: makes the joint read its reference position at load
  double low = 0.0, high = 0.0;
  double max_effort = 0.0;    ///< N m or N
  double max_velocity = 0.0;  ///< rad/s or m/s
};

/// A whole model file.
struct ModelDraft {
  std::string name_space;
  std::string label;  ///< short name for generated files, e.g. "left"
  std::string comment;
  bool ignore_inter_collision = false;
  std::vector<BodyDraft> bodies;
  std::vector<JointDraft> joints;

  const BodyDraft& body(const std::string& name) const;
};

/// The joint `name` that turns (or, `prismatic`, slides) `child` about the line through
/// `pivot_in_child` along `axis_in_child`, reading `position_now` with both bodies at their
/// drafted poses.
JointDraft connect(const std::string& name, const BodyDraft& parent, const BodyDraft& child,
                   const Eigen::Vector3d& axis_in_child, const Eigen::Vector3d& pivot_in_child,
                   double position_now, bool prismatic);

/// A body's centre of mass in its frame: the given one, else its geometry's (the hull's bounding
/// box centre, or its primitives' volume-weighted centre).
Eigen::Vector3d centreOfMass(const BodyDraft& body);

}  // namespace raven::model
