#include "ambf_like/proximity_sensor.hpp"

#include <btBulletDynamicsCommon.h>

#include <algorithm>

#include "ambf_like/bullet_conversions.hpp"
#include "collision_filter.hpp"

namespace ambf_like {

namespace {

/// The nearest hit that is not the sensor's own parent.
struct NearestExcept final : btCollisionWorld::ClosestRayResultCallback {
  NearestExcept(const btVector3& from, const btVector3& to, const btCollisionObject* excluded)
      : ClosestRayResultCallback(from, to), excluded_(excluded) {}
  bool needsCollision(btBroadphaseProxy* proxy) const override {
    return proxy->m_clientObject != excluded_ && ClosestRayResultCallback::needsCollision(proxy);
  }
  const btCollisionObject* excluded_;
};

}  // namespace

ProximitySensor::ProximitySensor(SensorSpec spec, std::string qualified_name,
                                 const RigidBody& parent)
    : spec_(std::move(spec)),
      qualified_name_(std::move(qualified_name)),
      parent_(parent),
      readings_(spec_.rays.size()) {
  for (auto& r : readings_) r.distance = spec_.range;
}

bool ProximitySensor::triggered() const {
  return std::any_of(readings_.begin(), readings_.end(), [](const auto& r) { return r.triggered; });
}

std::optional<RayReading> ProximitySensor::nearest() const {
  std::optional<RayReading> best;
  for (const auto& r : readings_) {
    if (r.triggered && (!best || r.distance < best->distance)) best = r;
  }
  return best;
}

std::pair<Vec3, Vec3> ProximitySensor::rayInWorld(std::size_t index) const {
  const Transform frame = parent_.pose() * spec_.location;
  const SensorRay& ray = spec_.rays.at(index);
  const Vec3 from = frame * ray.origin;
  return {from, from + frame.linear() * ray.direction * spec_.range};
}

void ProximitySensor::sense(const btCollisionWorld& world) {
  for (std::size_t i = 0; i < spec_.rays.size(); ++i) {
    const auto [from, to] = rayInWorld(i);
    NearestExcept hit(toBt(from), toBt(to), &parent_.bullet());
    world.rayTest(toBt(from), toBt(to), hit);
    RayReading& r = readings_[i];
    r.triggered = hit.hasHit();
    r.distance = r.triggered ? hit.m_closestHitFraction * spec_.range : spec_.range;
    if (r.triggered) {
      const auto* tag =
          static_cast<const detail::CollisionTag*>(hit.m_collisionObject->getUserPointer());
      r.body = tag ? tag->name : std::string("?");
      r.point = toEigen(hit.m_hitPointWorld);
      r.normal = toEigen(hit.m_hitNormalWorld);
    } else {
      r.body.clear();
    }
  }
}

}  // namespace ambf_like
