#include "shapes.hpp"

#include <LinearMath/btConvexHullComputer.h>

#include <cmath>
#include <fstream>
#include <stdexcept>

namespace raven::model {

namespace {

using Eigen::Isometry3d;
using Eigen::Vector3d;

/// Adds the quad (a, b, c, d), counter-clockwise seen from outside, as two triangles.
void quad(TriangleMesh& m, int a, int b, int c, int d) {
  m.triangles.push_back({a, b, c});
  m.triangles.push_back({a, c, d});
}

int vertex(TriangleMesh& m, const Vector3d& p) {
  m.vertices.push_back(p);
  return static_cast<int>(m.vertices.size()) - 1;
}

/// A surface of revolution about z: `profile` holds (radius, z) from bottom to top; the first
/// and last points may have radius 0 (poles).
TriangleMesh revolve(const std::vector<std::pair<double, double>>& profile, int around) {
  TriangleMesh m;
  std::vector<std::vector<int>> rings;
  for (const auto& [r, z] : profile) {
    std::vector<int> ring;
    if (r == 0.0) {
      ring.push_back(vertex(m, Vector3d(0, 0, z)));
    } else {
      for (int i = 0; i < around; ++i) {
        const double a = 2.0 * M_PI * i / around;
        ring.push_back(vertex(m, Vector3d(r * std::cos(a), r * std::sin(a), z)));
      }
    }
    rings.push_back(ring);
  }
  for (std::size_t k = 0; k + 1 < rings.size(); ++k) {
    const auto& lo = rings[k];
    const auto& hi = rings[k + 1];
    for (int i = 0; i < around; ++i) {
      const int j = (i + 1) % around;
      if (lo.size() == 1) {
        m.triangles.push_back(
            {lo[0], hi[static_cast<std::size_t>(j)], hi[static_cast<std::size_t>(i)]});
      } else if (hi.size() == 1) {
        m.triangles.push_back(
            {lo[static_cast<std::size_t>(i)], lo[static_cast<std::size_t>(j)], hi[0]});
      } else {
        quad(m, lo[static_cast<std::size_t>(i)], lo[static_cast<std::size_t>(j)],
             hi[static_cast<std::size_t>(j)], hi[static_cast<std::size_t>(i)]);
      }
    }
  }
  return m;
}

}  // namespace

void TriangleMesh::append(const TriangleMesh& other, const Isometry3d& pose) {
  const int base = static_cast<int>(vertices.size());
  for (const auto& v : other.vertices) vertices.push_back(pose * v);
  for (const auto& t : other.triangles)
    triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
}

void TriangleMesh::writeObj(const std::filesystem::path& file, const std::string& comment) const {
  std::filesystem::create_directories(file.parent_path());
  std::ofstream out(file);
  if (!out) throw std::runtime_error("cannot write " + file.string());
  out << "# " << comment << "\n";
  char line[128];
  for (const auto& v : vertices) {
    std::snprintf(line, sizeof line, "v %.9g %.9g %.9g\n", v.x(), v.y(), v.z());
    out << line;
  }
  for (const auto& t : triangles)
    out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
}

double Primitive::volume() const {
  switch (type) {
    case Type::Box:
      return size.x() * size.y() * size.z();
    case Type::Cylinder:
      return M_PI * size.x() * size.x() * size.y();
    case Type::Capsule:
      return M_PI * size.x() * size.x() * size.y() + 4.0 / 3.0 * M_PI * std::pow(size.x(), 3);
  }
  return 0.0;
}

TriangleMesh Primitive::tessellate(int segments) const {
  TriangleMesh local;
  if (type == Type::Box) {
    const Vector3d h = size / 2.0;
    const int n = segments;
    // Each face: an n x n grid, normal `axis`, spanned by `u` and `v` (u x v = normal).
    for (int axis = 0; axis < 3; ++axis) {
      for (int sign : {-1, 1}) {
        const int u = (axis + 1) % 3, v = (axis + 2) % 3;
        const int first = static_cast<int>(local.vertices.size());
        for (int i = 0; i <= n; ++i) {
          for (int j = 0; j <= n; ++j) {
            Vector3d p;
            p[axis] = sign * h[axis];
            p[u] = -h[u] + 2.0 * h[u] * i / n;
            p[v] = -h[v] + 2.0 * h[v] * j / n;
            vertex(local, p);
          }
        }
        for (int i = 0; i < n; ++i) {
          for (int j = 0; j < n; ++j) {
            const int a = first + i * (n + 1) + j;
            if (sign > 0) {
              quad(local, a, a + n + 1, a + n + 2, a + 1);
            } else {
              quad(local, a, a + 1, a + n + 2, a + n + 1);
            }
          }
        }
      }
    }
  } else {
    const double r = size.x(), half = size.y() / 2.0;
    std::vector<std::pair<double, double>> profile;
    const int along = std::max(2, segments / 2);
    if (type == Type::Cylinder) {
      profile.emplace_back(0.0, -half);
      for (int k = 0; k <= along; ++k) profile.emplace_back(r, -half + size.y() * k / along);
      profile.emplace_back(0.0, half);
    } else {
      const int cap = std::max(2, segments / 4);
      for (int k = 0; k <= cap; ++k) {
        const double a = -M_PI / 2 + M_PI / 2 * k / cap;
        profile.emplace_back(r * std::cos(a), -half + r * std::sin(a));
      }
      for (int k = 1; k < along; ++k) profile.emplace_back(r, -half + size.y() * k / along);
      for (int k = 0; k <= cap; ++k) {
        const double a = M_PI / 2 * k / cap;
        profile.emplace_back(r * std::cos(a), half + r * std::sin(a));
      }
      profile.front().first = 0.0;
      profile.back().first = 0.0;
    }
    local = revolve(profile, segments);
  }
  TriangleMesh placed;
  placed.append(local, pose);
  return placed;
}

namespace {

Primitive alongSegment(Primitive::Type type, const Vector3d& a, const Vector3d& b, double radius) {
  Primitive p;
  p.type = type;
  const Vector3d axis = b - a;
  p.size = Vector3d(radius, axis.norm(), 0.0);
  p.pose.linear() = Eigen::Quaterniond::FromTwoVectors(Vector3d::UnitZ(), axis).toRotationMatrix();
  p.pose.translation() = (a + b) / 2.0;
  return p;
}

}  // namespace

Primitive capsuleBetween(const Vector3d& a, const Vector3d& b, double radius) {
  return alongSegment(Primitive::Type::Capsule, a, b, radius);
}

Primitive cylinderBetween(const Vector3d& a, const Vector3d& b, double radius) {
  return alongSegment(Primitive::Type::Cylinder, a, b, radius);
}

std::vector<Vector3d> jawHullPoints(double length, double width, double thickness, int side) {
  std::vector<Vector3d> points;
  const double tip_radius = 0.3 * width;
  const int stations = 6;
  for (int k = 0; k <= stations; ++k) {
    const double x = (length - tip_radius) * k / stations;
    const double w = width * (1.0 - 0.4 * x / length);  // tapers to the tip
    for (double z : {-thickness / 2, thickness / 2}) {
      points.emplace_back(x, 0.0, z);
      points.emplace_back(x, side * w, z);
    }
  }
  for (int k = 1; k <= 4; ++k) {  // rounded tip
    const double a = M_PI / 2 * k / 4;
    for (double z : {-thickness / 2, thickness / 2}) {
      points.emplace_back(length - tip_radius + tip_radius * std::sin(a),
                          side * tip_radius * (1.0 - std::cos(a)) * 0.999, z);
    }
  }
  return points;
}

TriangleMesh convexHull(const std::vector<Vector3d>& points) {
  std::vector<double> coords;
  for (const auto& p : points) coords.insert(coords.end(), {p.x(), p.y(), p.z()});
  btConvexHullComputer hull;
  hull.compute(coords.data(), 3 * static_cast<int>(sizeof(double)), static_cast<int>(points.size()),
               0.0, 0.0);
  TriangleMesh m;
  for (int i = 0; i < hull.vertices.size(); ++i) {
    const auto& v = hull.vertices[i];
    m.vertices.emplace_back(v.x(), v.y(), v.z());
  }
  for (int f = 0; f < hull.faces.size(); ++f) {
    const auto* edge = &hull.edges[hull.faces[f]];
    const int first = edge->getSourceVertex();
    const auto* e = edge->getNextEdgeOfFace();
    int previous = e->getSourceVertex();
    for (e = e->getNextEdgeOfFace(); e != edge; e = e->getNextEdgeOfFace()) {
      const int next = e->getSourceVertex();
      m.triangles.push_back({first, previous, next});
      previous = next;
    }
  }
  return m;
}

}  // namespace raven::model
