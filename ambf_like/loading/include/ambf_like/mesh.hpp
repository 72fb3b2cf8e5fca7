#pragma once
// Triangle meshes read from STL, OBJ, 3DS or DAE files through assimp, and tetrahedral volume
// meshes from legacy VTK files, loaded once and shared.

#include <array>
#include <filesystem>
#include <map>
#include <memory>
#include <vector>

#include "ambf_like/load_error.hpp"
#include "ambf_like/transform.hpp"

namespace ambf_like {

/// Geometry of one mesh file: vertices welded by position, node transforms applied. A volume
/// mesh (.vtk) has tetrahedra too; its triangles are then their boundary faces, outward.
struct Mesh {
  std::filesystem::path file;
  std::vector<Vec3> vertices;
  std::vector<std::array<int, 3>> triangles;
  std::vector<std::array<int, 4>> tetrahedra;  ///< positive volume; empty for surface meshes

  /// Mean of the vertices (AMBF's default inertial offset for mesh bodies).
  Vec3 centroid() const;
  /// The signed volume of the tetrahedron of these four vertex indices (positive when the fourth
  /// lies on the side the first three's right-handed normal points to).
  double volume(const std::array<int, 4>& tetrahedron) const;
};

/// Loads each mesh file once (assimp) and hands out shared, immutable copies.
class MeshLibrary {
 public:
  /// Throws LoadError naming `referenced_from` when the file is missing, unreadable, empty or of
  /// another format than those above (whatever assimp could read).
  std::shared_ptr<const Mesh> load(const std::filesystem::path& file,
                                   const SourceRef& referenced_from);

  std::size_t size() const { return cache_.size(); }

 private:
  std::map<std::filesystem::path, std::shared_ptr<const Mesh>> cache_;
};

}  // namespace ambf_like
