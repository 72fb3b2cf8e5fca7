#pragma once
// A rigid body of the running simulation: its pose and velocities.

#include <memory>
#include <string>

#include "ambf_like/body_spec.hpp"

class btRigidBody;
class btMotionState;

namespace ambf_like {

/// One rigid body of a World. Poses are of the body (mesh) frame unless named otherwise.
class RigidBody {
 public:
  /// Built by World; `com_in_body` is the centre-of-mass frame in the body frame.
  RigidBody(BodySpec spec, std::string qualified_name, std::unique_ptr<btRigidBody> body,
            const Transform& com_in_body, std::size_t collision_vertices);
  ~RigidBody();
  RigidBody(const RigidBody&) = delete;
  RigidBody& operator=(const RigidBody&) = delete;

  const std::string& name() const { return spec_.name; }
  /// Model namespace + name, unique within a World.
  const std::string& qualifiedName() const { return qualified_name_; }
  const BodySpec& spec() const { return spec_; }

  Transform pose() const;
  Transform centerOfMassPose() const;
  Vec3 linearVelocity() const;   ///< of the centre of mass, world frame
  Vec3 angularVelocity() const;  ///< world frame
  double mass() const { return spec_.mass; }
  bool isStatic() const { return spec_.mass == 0.0; }
  std::size_t collisionVertexCount() const { return collision_vertices_; }
  bool isFinite() const;
  /// A dynamic body Bullet deactivated with its resting island (RigidBodySleep): not stepped
  /// until woken. Never a static body.
  bool isAsleep() const;

  /// The Bullet body. For a link of an articulation (reduced coordinates) it is a mirror outside
  /// the Bullet world, updated after every step: read it, do not push it.
  btRigidBody& bullet() { return *body_; }
  const btRigidBody& bullet() const { return *body_; }

 private:
  BodySpec spec_;
  std::string qualified_name_;
  std::unique_ptr<btRigidBody> body_;
  Transform body_in_com_;
  std::size_t collision_vertices_;
};

}  // namespace ambf_like
