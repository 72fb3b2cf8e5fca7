#pragma once
// Fewer triangles for the eye: vertex clustering (Rossignac and Borrel 1993). Vertices in one cell
// of a grid over the mesh's bounds merge into their mean; triangles that collapse are dropped.
// A CAD mesh with fine detail (AMBF's Raven links: 28,000 triangles each) keeps its outline at a
// fraction of the triangles, which a software rasteriser draws in time.

#include "ambf_like/mesh.hpp"

namespace viewer::detail {

/// The mesh's triangles with vertices merged on a grid of `cells` along each side of its bounds
/// (a long thin shaft keeps its girth); degenerate and repeated triangles are gone.
ambf_like::Mesh clusterVertices(const ambf_like::Mesh& mesh, int cells);

}  // namespace viewer::detail
