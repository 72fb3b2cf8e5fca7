// Fuzz target: a mesh file (STL, OBJ, COLLADA, VTK or 3DS, chosen by the input's first byte) read
// by the mesh library. A loaded mesh must be usable as it is: finite vertices, triangle and
// tetrahedron indices in range, tetrahedra of positive volume.

#include <array>
#include <cmath>
#include <cstdint>
#include <string>

#include "ambf_like/load_error.hpp"
#include "ambf_like/mesh.hpp"
#include "fuzz_file.hpp"

namespace {

template <std::size_t N>
void checkIndices(const std::vector<std::array<int, N>>& cells, std::size_t vertices,
                  const char* what) {
  for (const auto& cell : cells) {
    for (int i : cell) {
      if (i < 0 || static_cast<std::size_t>(i) >= vertices) {
        fuzz::fail(std::string(what) + " index out of range");
      }
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  static constexpr std::array<const char*, 5> kExtensions{"stl", "obj", "dae", "vtk", "3ds"};
  const auto file = fuzz::asFile(data + 1, size - 1,
                                 std::string("mesh.") + kExtensions[data[0] % kExtensions.size()]);
  ambf_like::MeshLibrary library;
  try {
    const auto mesh = library.load(file, ambf_like::SourceRef{"fuzz.yaml", 1, "mesh"});
    for (const auto& v : mesh->vertices) {
      if (!v.allFinite()) fuzz::fail("a loaded mesh has a non-finite vertex");
    }
    checkIndices(mesh->triangles, mesh->vertices.size(), "triangle");
    checkIndices(mesh->tetrahedra, mesh->vertices.size(), "tetrahedron");
    for (const auto& t : mesh->tetrahedra) {
      if (!(mesh->volume(t) > 0.0)) fuzz::fail("a loaded tetrahedron has no positive volume");
    }
  } catch (const ambf_like::LoadError&) {
  }
  return 0;
}
