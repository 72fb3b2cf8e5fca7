#include "tessellation.hpp"

#include <BulletCollision/CollisionShapes/btShapeHull.h>
#include <btBulletCollisionCommon.h>

#include <cmath>

#include "ambf_like/bullet_conversions.hpp"

namespace viewer::detail {

namespace {

using V = Eigen::Vector3f;
constexpr int kSegments = 24;  ///< around a round shape
constexpr double kPlaneHalfSize = 1.0;

/// The rotation taking +Z to the shape's long axis.
Eigen::Matrix3f zTo(ambf_like::Axis axis) {
  switch (axis) {
    case ambf_like::Axis::X:
      return Eigen::AngleAxisf(static_cast<float>(M_PI / 2), V::UnitY()).toRotationMatrix();
    case ambf_like::Axis::Y:
      return Eigen::AngleAxisf(static_cast<float>(-M_PI / 2), V::UnitX()).toRotationMatrix();
    case ambf_like::Axis::Z:
      break;
  }
  return Eigen::Matrix3f::Identity();
}

void box(TriangleMesh& m, const V& half) {
  for (int axis = 0; axis < 3; ++axis) {
    for (float sign : {-1.0f, 1.0f}) {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      auto corner = [&](float su, float sv) {
        V p;
        p[axis] = sign * half[axis];
        p[u] = su * half[u];
        p[v] = sv * half[v];
        return p;
      };
      if (sign > 0) {
        m.add(corner(-1, -1), corner(1, -1), corner(1, 1));
        m.add(corner(-1, -1), corner(1, 1), corner(-1, 1));
      } else {
        m.add(corner(-1, -1), corner(1, 1), corner(1, -1));
        m.add(corner(-1, -1), corner(-1, 1), corner(1, 1));
      }
    }
  }
}

/// A surface of revolution about +Z through the (radius, z) profile points, bottom to top.
void revolve(TriangleMesh& m, const std::vector<std::pair<float, float>>& profile,
             const Eigen::Matrix3f& orient) {
  auto at = [&](std::size_t k, int s) {
    const float a = static_cast<float>(2.0 * M_PI * s / kSegments);
    return V(orient *
             V(profile[k].first * std::cos(a), profile[k].first * std::sin(a), profile[k].second));
  };
  for (std::size_t k = 0; k + 1 < profile.size(); ++k) {
    for (int s = 0; s < kSegments; ++s) {
      const V a = at(k, s), b = at(k, s + 1), c = at(k + 1, s + 1), d = at(k + 1, s);
      if (profile[k].first > 0.0f) m.add(a, b, c);
      if (profile[k + 1].first > 0.0f) m.add(a, c, d);
    }
  }
}

/// Profile of a sphere of `radius` centred at z = `centre`, from `from` to `to` latitude.
void arc(std::vector<std::pair<float, float>>& profile, float radius, float centre, float from,
         float to) {
  const int rings = kSegments / 4;
  for (int i = 0; i <= rings; ++i) {
    const float lat = from + (to - from) * static_cast<float>(i) / rings;
    profile.emplace_back(radius * std::cos(lat), centre + radius * std::sin(lat));
  }
}

TriangleMesh sphere(float r) {
  TriangleMesh m;
  std::vector<std::pair<float, float>> profile;
  arc(profile, r, 0.0f, static_cast<float>(-M_PI / 2), static_cast<float>(M_PI / 2));
  revolve(m, profile, Eigen::Matrix3f::Identity());
  return m;
}

TriangleMesh capsule(float r, float cylinder_height, const Eigen::Matrix3f& orient) {
  TriangleMesh m;
  std::vector<std::pair<float, float>> profile;
  const float h = cylinder_height / 2;
  arc(profile, r, -h, static_cast<float>(-M_PI / 2), 0.0f);
  arc(profile, r, h, 0.0f, static_cast<float>(M_PI / 2));
  revolve(m, profile, orient);
  return m;
}

TriangleMesh cylinder(float r, float height, const Eigen::Matrix3f& orient) {
  TriangleMesh m;
  const float h = height / 2;
  revolve(m, {{0.0f, -h}, {r, -h}, {r, h}, {0.0f, h}}, orient);
  return m;
}

TriangleMesh cone(float r, float height, const Eigen::Matrix3f& orient) {
  TriangleMesh m;
  const float h = height / 2;  // centred, as Bullet's cone
  revolve(m, {{0.0f, -h}, {r, -h}, {0.0f, h}}, orient);
  return m;
}

TriangleMesh plane(const V& normal, float offset) {
  TriangleMesh m;
  const Eigen::Quaternionf q = Eigen::Quaternionf::FromTwoVectors(V::UnitZ(), normal);
  const float s = static_cast<float>(kPlaneHalfSize);
  auto p = [&](float x, float y) { return V(q * V(x, y, 0.0f) + offset * normal); };
  m.add(p(-s, -s), p(s, -s), p(s, s));
  m.add(p(-s, -s), p(s, s), p(-s, s));
  return m;
}

ambf_like::Axis axisOf(int up) {
  return up == 0 ? ambf_like::Axis::X : up == 1 ? ambf_like::Axis::Y : ambf_like::Axis::Z;
}

V toFloat(const btVector3& p) {
  return ambf_like::toEigen(p).cast<float>();
}

/// Collects a concave shape's triangles.
class TriangleCollector : public btTriangleCallback {
 public:
  explicit TriangleCollector(TriangleMesh& mesh) : mesh_(mesh) {}
  void processTriangle(btVector3* t, int, int) override {
    mesh_.add(toFloat(t[0]), toFloat(t[1]), toFloat(t[2]));
  }

 private:
  TriangleMesh& mesh_;
};

}  // namespace

TriangleMesh tessellate(const ambf_like::PrimitiveShape& s, double scale) {
  const auto f = [scale](double v) { return static_cast<float>(v * scale); };
  switch (s.type) {
    case ambf_like::PrimitiveType::Box: {
      TriangleMesh m;
      box(m, (s.box_size * scale / 2).cast<float>());
      return m;
    }
    case ambf_like::PrimitiveType::Sphere:
      return sphere(f(s.radius));
    case ambf_like::PrimitiveType::Cylinder:
      return cylinder(f(s.radius), f(s.height), zTo(s.axis));
    case ambf_like::PrimitiveType::Capsule:
      return capsule(f(s.radius), f(s.height), zTo(s.axis));
    case ambf_like::PrimitiveType::Cone:
      return cone(f(s.radius), f(s.height), zTo(s.axis));
    case ambf_like::PrimitiveType::Plane:
      return plane(s.plane_normal.normalized().cast<float>(), f(s.plane_offset));
  }
  return {};
}

TriangleMesh tessellate(const btCollisionShape& shape) {
  TriangleMesh m;
  if (const auto* compound = dynamic_cast<const btCompoundShape*>(&shape)) {
    for (int i = 0; i < compound->getNumChildShapes(); ++i) {
      m.append(tessellate(*compound->getChildShape(i)),
               ambf_like::toEigen(compound->getChildTransform(i)));
    }
  } else if (const auto* b = dynamic_cast<const btBoxShape*>(&shape)) {
    box(m, toFloat(b->getHalfExtentsWithMargin()));
  } else if (const auto* s = dynamic_cast<const btSphereShape*>(&shape)) {
    m = sphere(static_cast<float>(s->getRadius()));
  } else if (const auto* c = dynamic_cast<const btCapsuleShape*>(&shape)) {
    m = capsule(static_cast<float>(c->getRadius()), static_cast<float>(2 * c->getHalfHeight()),
                zTo(axisOf(c->getUpAxis())));
  } else if (const auto* cyl = dynamic_cast<const btCylinderShape*>(&shape)) {
    const int up = cyl->getUpAxis();
    const btVector3 half = cyl->getHalfExtentsWithMargin();
    m = cylinder(static_cast<float>(cyl->getRadius()), static_cast<float>(2 * half[up]),
                 zTo(axisOf(up)));
  } else if (const auto* cn = dynamic_cast<const btConeShape*>(&shape)) {
    m = cone(static_cast<float>(cn->getRadius()), static_cast<float>(cn->getHeight()),
             zTo(axisOf(cn->getConeUpIndex())));
  } else if (const auto* p = dynamic_cast<const btStaticPlaneShape*>(&shape)) {
    m = plane(toFloat(p->getPlaneNormal()), static_cast<float>(p->getPlaneConstant()));
  } else if (const auto* convex = dynamic_cast<const btConvexShape*>(&shape)) {
    btShapeHull hull(convex);
    hull.buildHull(convex->getMargin());
    const btVector3* v = hull.getVertexPointer();
    const unsigned int* index = hull.getIndexPointer();
    auto at = [&](int i) { return toFloat(v[index[i]]); };
    for (int t = 0; t + 2 < hull.numIndices(); t += 3) m.add(at(t), at(t + 1), at(t + 2));
  } else if (const auto* concave = dynamic_cast<const btConcaveShape*>(&shape)) {
    TriangleCollector collect(m);
    const btVector3 big(1e4, 1e4, 1e4);
    concave->processAllTriangles(&collect, -big, big);
  }
  return m;
}

}  // namespace viewer::detail
