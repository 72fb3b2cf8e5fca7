#pragma once
// Tetrahedral volume meshes the model generator writes (legacy VTK), for soft bodies that must
// resist being squeezed through their thickness.

#include <Eigen/Geometry>
#include <array>
#include <filesystem>
#include <string>
#include <vector>

namespace raven::model {

/// Points and tetrahedra, written as a VTK UNSTRUCTURED_GRID.
struct TetMesh {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<int, 4>> tetrahedra;

  void writeVtk(const std::filesystem::path& file, const std::string& comment) const;
};

/// A solid ring about z: the tube's cross-section is an ellipse of half-width `minor` (radial)
/// and half-height `half_height`, sampled by `tube_segments` points around an axis point, at
/// `ring_segments` stations around the ring. Each sector of a station joined to the next is a
/// prism cut into three tetrahedra by the global-index rule (Dompierre et al. 1999), so
/// neighbouring prisms share their faces.
TetMesh solidRing(double major, double minor, double half_height, int ring_segments,
                  int tube_segments);

}  // namespace raven::model
