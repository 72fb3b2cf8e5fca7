#include "ambf_like/step_guard.hpp"

#include <BulletSoftBody/btSoftBody.h>
#include <spdlog/fmt/fmt.h>

#include <algorithm>
#include <cmath>

#include "ambf_like/bullet_conversions.hpp"

namespace ambf_like {

namespace {

/// The least scene size (m): a lone body's scene is taken as a metre across.
constexpr double kLeastSceneSize = 1.0;
/// How far beyond the scene's box a body may go, in scene sizes.
constexpr double kBoundsMargin = 10.0;
/// The most of the scene's size a body may cross in one step.
constexpr double kMostSceneShareAStep = 0.1;

std::string describe(const std::string& body, int node) {
  return node < 0 ? fmt::format("rigid body '{}'", body)
                  : fmt::format("soft body '{}' node {}", body, node);
}

}  // namespace

SimulationDiverged::SimulationDiverged(std::string body, int node, std::uint64_t step, double time,
                                       const std::string& problem)
    : std::runtime_error(fmt::format("the simulation diverged at step {} (t = {:.4f} s): {} {}",
                                     step, time, describe(body, node), problem)),
      body_(std::move(body)),
      node_(node),
      step_(step),
      time_(time) {}

StepGuard::StepGuard(const std::vector<Eigen::Vector3d>& scene_points, double step,
                     const Eigen::Vector3d& gravity) {
  Eigen::AlignedBox3d scene(Eigen::Vector3d::Zero());
  if (!scene_points.empty()) scene = Eigen::AlignedBox3d(scene_points.front());
  for (const auto& p : scene_points) {
    if (p.allFinite()) scene.extend(p);
  }
  const double size = std::max(kLeastSceneSize, scene.diagonal().norm());
  const double g = gravity.norm();
  // A fall across the scene and its margins above and below it.
  const double fall_across = std::sqrt(2.0 * g * (1.0 + 2.0 * kBoundsMargin) * size);
  speed_limit_ = std::max(kMostSceneShareAStep * size / step, fall_across);
  const Eigen::Vector3d margin = Eigen::Vector3d::Constant(kBoundsMargin * size);
  bounds_ = Eigen::AlignedBox3d(scene.min() - margin, scene.max() + margin);
  if (g > 0.0) {
    // Downwards the bounds reach as far as a fall takes a body before it is too fast: a body
    // that falls off the scene is stopped by the speed limit, not by the bounds.
    const Eigen::Vector3d fall = gravity / g * (speed_limit_ * speed_limit_ / (2.0 * g));
    bounds_.extend(bounds_.min() + fall.cwiseMin(0.0));
    bounds_.extend(bounds_.max() + fall.cwiseMax(0.0));
  }
}

std::string StepGuard::problemOf(const Vec3& position, const Vec3& velocity) const {
  if (!position.allFinite() || !velocity.allFinite()) {
    return fmt::format("is not finite (position {} {} {}, velocity {} {} {})", position.x(),
                       position.y(), position.z(), velocity.x(), velocity.y(), velocity.z());
  }
  if (!bounds_.contains(position)) {
    return fmt::format(
        "left the world's bounds: at ({:.4g}, {:.4g}, {:.4g}) m, outside ({:.4g}..{:.4g}, "
        "{:.4g}..{:.4g}, {:.4g}..{:.4g}) m",
        position.x(), position.y(), position.z(), bounds_.min().x(), bounds_.max().x(),
        bounds_.min().y(), bounds_.max().y(), bounds_.min().z(), bounds_.max().z());
  }
  if (velocity.norm() > speed_limit_) {
    return fmt::format("moves at {:.6g} m/s, faster than the scene allows ({:.4g} m/s)",
                       velocity.norm(), speed_limit_);
  }
  return {};
}

bool StepGuard::fine(const Vec3& position, const Vec3& velocity) const {
  // Written so that a NaN fails every comparison: nothing here is true of it.
  const bool inside = (position.array() >= bounds_.min().array()).all() &&
                      (position.array() <= bounds_.max().array()).all();
  return inside && velocity.squaredNorm() <= speed_limit_ * speed_limit_;
}

void StepGuard::check(const std::vector<std::unique_ptr<RigidBody>>& bodies,
                      const std::vector<std::unique_ptr<SoftBody>>& soft_bodies, std::uint64_t step,
                      double time) const {
  for (const auto& body : bodies) {
    if (body->isStatic()) continue;
    const Vec3 position = body->centerOfMassPose().translation();
    const Vec3 velocity = body->linearVelocity();
    if (fine(position, velocity) && body->angularVelocity().allFinite()) continue;
    std::string problem = problemOf(position, velocity);
    if (problem.empty()) problem = "turns at a speed that is not finite";
    throw SimulationDiverged(body->qualifiedName(), -1, step, time, problem);
  }
  for (const auto& soft : soft_bodies) {
    if (soft->isAsleep()) continue;  // it has not moved since it was checked awake
    const btSoftBody& b = soft->bullet();
    for (int i = 0; i < b.m_nodes.size(); ++i) {
      const btSoftBody::Node& node = b.m_nodes[i];
      if (node.m_im <= 0.0) continue;  // fixed
      const Vec3 position = toEigen(node.m_x), velocity = toEigen(node.m_v);
      if (fine(position, velocity)) continue;
      throw SimulationDiverged(soft->qualifiedName(), i, step, time, problemOf(position, velocity));
    }
  }
}

}  // namespace ambf_like
