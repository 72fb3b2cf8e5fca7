#include "ambf_like/proximity_sensor.hpp"

#include <BulletSoftBody/btSoftBody.h>
#include <btBulletDynamicsCommon.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "ambf_like/bullet_conversions.hpp"
#include "ambf_like/dynamics/collision_filter.hpp"

namespace ambf_like {

namespace {

/// The nearest hit on a rigid body that is not the sensor's own parent (soft bodies are tested
/// by nearestSoftHit: Bullet's soft-body ray test tries every face of the body).
struct NearestRigidExcept final : btCollisionWorld::ClosestRayResultCallback {
  NearestRigidExcept(const btVector3& from, const btVector3& to, const btCollisionObject* excluded)
      : ClosestRayResultCallback(from, to), excluded_(excluded) {}
  bool needsCollision(btBroadphaseProxy* proxy) const override {
    const auto* object = static_cast<const btCollisionObject*>(proxy->m_clientObject);
    return object != excluded_ && btSoftBody::upcast(object) == nullptr &&
           ClosestRayResultCallback::needsCollision(proxy);
  }
  const btCollisionObject* excluded_;
};

/// A ray's hit on a soft body's face.
struct SoftHit {
  const btSoftBody* body = nullptr;
  int face = -1;
  btScalar fraction = 1.0;  ///< along from -> to
  btVector3 normal;
};

/// Where the segment from -> to first crosses a triangle (Moller-Trumbore), as a fraction.
std::optional<btScalar> crossing(const btVector3& from, const btVector3& to, const btVector3& a,
                                 const btVector3& b, const btVector3& c) {
  const btVector3 d = to - from, e1 = b - a, e2 = c - a;
  const btVector3 p = d.cross(e2);
  const btScalar det = e1.dot(p);
  if (std::abs(det) < 1e-18) return std::nullopt;
  const btVector3 t = from - a;
  const btScalar u = t.dot(p) / det;
  if (u < 0.0 || u > 1.0) return std::nullopt;
  const btVector3 q = t.cross(e1);
  const btScalar v = d.dot(q) / det;
  if (v < 0.0 || u + v > 1.0) return std::nullopt;
  const btScalar f = e2.dot(q) / det;
  if (f < 0.0 || f > 1.0) return std::nullopt;
  return f;
}

/// The nearest face of any soft body the segment crosses before `best` (a fraction), testing
/// only the faces whose bounding box the segment's box overlaps.
SoftHit nearestSoftHit(const btCollisionWorld& world, const btVector3& from, const btVector3& to,
                       btScalar best) {
  SoftHit hit;
  hit.fraction = best;
  btVector3 low = from, high = from;
  low.setMin(to);
  high.setMax(to);
  auto apart = [&](const btVector3& lo, const btVector3& hi) {
    return hi.x() < low.x() || hi.y() < low.y() || hi.z() < low.z() || lo.x() > high.x() ||
           lo.y() > high.y() || lo.z() > high.z();
  };
  const auto& objects = world.getCollisionObjectArray();
  for (int o = 0; o < objects.size(); ++o) {
    const btSoftBody* soft = btSoftBody::upcast(objects[o]);
    if (soft == nullptr || apart(soft->m_bounds[0], soft->m_bounds[1])) continue;
    for (int f = 0; f < soft->m_faces.size(); ++f) {
      const btSoftBody::Face& face = soft->m_faces[f];
      const btVector3 &a = face.m_n[0]->m_x, &b = face.m_n[1]->m_x, &c = face.m_n[2]->m_x;
      btVector3 lo = a, hi = a;
      lo.setMin(b);
      lo.setMin(c);
      hi.setMax(b);
      hi.setMax(c);
      if (apart(lo, hi)) continue;
      const auto t = crossing(from, to, a, b, c);
      if (!t || *t >= hit.fraction) continue;
      btVector3 normal = (b - a).cross(c - a).normalized();
      if (normal.dot(to - from) > 0.0) normal = -normal;
      hit = {soft, f, *t, normal};
    }
  }
  return hit;
}

}  // namespace

ProximitySensor::ProximitySensor(SensorSpec spec, std::string qualified_name,
                                 const RigidBody& parent)
    : spec_(std::move(spec)),
      qualified_name_(std::move(qualified_name)),
      parent_(parent),
      readings_(spec_.rays.size()) {
  for (auto& r : readings_) r.distance = spec_.range;
}

void ProximitySensor::setActive(bool active) {
  active_ = active;
  if (active) return;
  for (auto& r : readings_) {
    r = RayReading{};
    r.distance = spec_.range;
  }
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
    const auto [start, end] = rayInWorld(i);
    const btVector3 from = toBt(start), to = toBt(end);
    NearestRigidExcept rigid(from, to, &parent_.bullet());
    world.rayTest(from, to, rigid);
    const SoftHit soft =
        nearestSoftHit(world, from, to, rigid.hasHit() ? rigid.m_closestHitFraction : 1.0);
    RayReading& r = readings_[i];
    r = RayReading{};
    r.distance = spec_.range;
    const btCollisionObject* object = soft.body ? soft.body : rigid.m_collisionObject;
    if (object == nullptr) continue;
    const btScalar fraction = soft.body ? soft.fraction : rigid.m_closestHitFraction;
    const auto* tag = static_cast<const detail::CollisionTag*>(object->getUserPointer());
    r.triggered = true;
    r.distance = fraction * spec_.range;
    r.body = tag ? tag->name : std::string("?");
    r.point = toEigen(from.lerp(to, fraction));
    r.normal = toEigen(soft.body ? soft.normal : rigid.m_hitNormalWorld);
    if (soft.body) {
      r.soft_face = soft.face;
      const btSoftBody::Face& face = soft.body->m_faces[soft.face];
      for (std::size_t k = 0; k < 3; ++k) {
        r.face_nodes[k] = static_cast<int>(face.m_n[k] - &soft.body->m_nodes[0]);
      }
    }
  }
}

}  // namespace ambf_like
