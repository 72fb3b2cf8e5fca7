#pragma once
// The check after every step that a world has not blown up: finite, inside its bounds, not faster
// than its scene allows.

#include <Eigen/Geometry>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "ambf_like/rigid_body.hpp"
#include "ambf_like/soft_body.hpp"

namespace ambf_like {

/// A step that left the physical: which body (and node of a soft body), at which step and
/// simulated time, and what was wrong. World::step throws it; the world is then unusable.
class SimulationDiverged : public std::runtime_error {
 public:
  SimulationDiverged(std::string body, int node, std::uint64_t step, double time,
                     const std::string& problem);

  const std::string& body() const { return body_; }  ///< qualified name
  int node() const { return node_; }                 ///< -1 for a rigid body
  std::uint64_t step() const { return step_; }       ///< the step that ended so (1 = the first)
  double time() const { return time_; }              ///< simulated, at that step's end (s)

 private:
  std::string body_;
  int node_;
  std::uint64_t step_;
  double time_;
};

/// What a step is held to, from the scene as it was built. Its size L is the diagonal of the box
/// around every body's centre of mass and every soft-body node, at least 1 m. Every moving body
/// and node must move no faster than a tenth of L per step or than a fall across the scene and
/// 10 L above and below it, whichever is more (the peg-transfer scene at 1 ms: 100 m/s, where its
/// fastest real motion is under 1 m/s), and stay inside the bounds: the scene's box grown by
/// 10 L on each side, and downwards (along gravity) by as far as a body falls before it reaches
/// that speed (510 m at 100 m/s), so that a body falling off a scene with no floor (as AMBF
/// lets it) is stopped by the speed it reaches, after v / g (10 s), and one flung sideways or up
/// by the bounds.
class StepGuard {
 public:
  StepGuard(const std::vector<Eigen::Vector3d>& scene_points, double step,
            const Eigen::Vector3d& gravity);

  /// Throws SimulationDiverged naming the first body or node that is not finite, out of the
  /// bounds or too fast.
  void check(const std::vector<std::unique_ptr<RigidBody>>& bodies,
             const std::vector<std::unique_ptr<SoftBody>>& soft_bodies, std::uint64_t step,
             double time) const;

  const Eigen::AlignedBox3d& bounds() const { return bounds_; }
  double speedLimit() const { return speed_limit_; }  ///< m/s

 private:
  /// Whether `position` and `velocity` are finite, inside the bounds and within the speed.
  bool fine(const Vec3& position, const Vec3& velocity) const;
  /// What is wrong with `position` and `velocity` (empty when nothing is).
  std::string problemOf(const Vec3& position, const Vec3& velocity) const;

  Eigen::AlignedBox3d bounds_;
  double speed_limit_ = 0;
};

}  // namespace ambf_like
