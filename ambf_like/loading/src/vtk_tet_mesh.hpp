#pragma once
// Tetrahedral volume meshes in VTK's legacy ASCII format (an UNSTRUCTURED_GRID of tetrahedra, as
// TetGen, gmsh and Bullet's own deformable demos write them).

#include <filesystem>

#include "ambf_like/mesh.hpp"

namespace ambf_like::detail {

/// Reads `file` into a Mesh whose tetrahedra are the file's cells (each turned to positive
/// volume) and whose triangles are their boundary faces, outward. Throws LoadError naming the
/// file and line of anything it cannot take: other cell types, indices out of range, degenerate
/// or non-finite cells, a truncated file.
Mesh readVtkTetMesh(const std::filesystem::path& file);

}  // namespace ambf_like::detail
