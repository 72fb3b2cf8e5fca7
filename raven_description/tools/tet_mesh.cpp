#include "tet_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace raven::model {

namespace {

/// A prism's vertices, bottom triangle 0-1-2 under top 3-4-5, cut into three tetrahedra. The
/// cut depends only on the global indices, so a quad face shared by two prisms is cut the same
/// way in both.
std::array<std::array<int, 4>, 3> splitPrism(const std::array<int, 6>& v) {
  // The prism's symmetries that bring each vertex to position 0.
  static constexpr int kRotation[6][6] = {{0, 1, 2, 3, 4, 5}, {1, 2, 0, 4, 5, 3},
                                          {2, 0, 1, 5, 3, 4}, {3, 5, 4, 0, 2, 1},
                                          {4, 3, 5, 1, 0, 2}, {5, 4, 3, 2, 1, 0}};
  const int lowest = static_cast<int>(std::min_element(v.begin(), v.end()) - v.begin());
  std::array<int, 6> p{};
  for (int i = 0; i < 6; ++i) p[i] = v[kRotation[lowest][i]];
  if (std::min(p[1], p[5]) < std::min(p[2], p[4])) {
    return {{{p[0], p[1], p[2], p[5]}, {p[0], p[1], p[5], p[4]}, {p[0], p[4], p[5], p[3]}}};
  }
  return {{{p[0], p[1], p[2], p[4]}, {p[0], p[4], p[2], p[5]}, {p[0], p[4], p[5], p[3]}}};
}

}  // namespace

void TetMesh::writeVtk(const std::filesystem::path& file, const std::string& comment) const {
  std::filesystem::create_directories(file.parent_path());
  std::ofstream out(file);
  if (!out) throw std::runtime_error("cannot write " + file.string());
  out << "# vtk DataFile Version 2.0\n" << comment << "\nASCII\nDATASET UNSTRUCTURED_GRID\n";
  out << "POINTS " << vertices.size() << " double\n";
  char line[128];
  for (const auto& v : vertices) {
    std::snprintf(line, sizeof line, "%.9g %.9g %.9g\n", v.x(), v.y(), v.z());
    out << line;
  }
  out << "CELLS " << tetrahedra.size() << ' ' << 5 * tetrahedra.size() << '\n';
  for (const auto& t : tetrahedra) {
    out << "4 " << t[0] << ' ' << t[1] << ' ' << t[2] << ' ' << t[3] << '\n';
  }
  out << "CELL_TYPES " << tetrahedra.size() << '\n';
  for (std::size_t i = 0; i < tetrahedra.size(); ++i) out << "10\n";
}

TetMesh solidRing(double major, double minor, double half_height, int ring_segments,
                  int tube_segments) {
  TetMesh m;
  const int per_station = tube_segments + 1;  // the axis point, then the surface
  for (int i = 0; i < ring_segments; ++i) {
    const double u = 2.0 * M_PI * i / ring_segments;
    const Eigen::Vector3d radial(std::cos(u), std::sin(u), 0.0);
    m.vertices.push_back(major * radial);
    for (int j = 0; j < tube_segments; ++j) {
      const double v = 2.0 * M_PI * j / tube_segments;
      m.vertices.push_back((major + minor * std::cos(v)) * radial +
                           Eigen::Vector3d(0, 0, half_height * std::sin(v)));
    }
  }
  auto axis = [&](int i) { return (i % ring_segments) * per_station; };
  auto surface = [&](int i, int j) { return axis(i) + 1 + j % tube_segments; };
  for (int i = 0; i < ring_segments; ++i) {
    for (int j = 0; j < tube_segments; ++j) {
      const std::array<int, 6> prism{axis(i),     surface(i, j),     surface(i, j + 1),
                                     axis(i + 1), surface(i + 1, j), surface(i + 1, j + 1)};
      for (const auto& t : splitPrism(prism)) m.tetrahedra.push_back(t);
    }
  }
  return m;
}

}  // namespace raven::model
