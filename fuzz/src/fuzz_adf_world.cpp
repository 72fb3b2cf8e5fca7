// Fuzz target: AMBF description files that the loader accepts, built into a world and stepped,
// as every program that opens a model does. The first byte picks what the rest is: even, a
// multibody file (ADF) in AMBF's default world; odd, a world file under a small scene of a
// board, a hinged box and a soft cube of five tetrahedra. A soft body's mesh may name `tet.vtk`,
// which is there beside the input, so the soft bodies' materials and settings are reached as well.
// What the loader takes must build and run: the loader refuses a bad file by its line
// (LoadError), and only the step guard's SimulationDiverged (naming the body and step) may end a
// run. A crash, hang, sanitizer report or any other exception (an element the world refuses that
// the loader let through) is a finding.

#include <cstdint>
#include <string_view>

#include "ambf_like/mesh.hpp"
#include "ambf_like/scene_loader.hpp"
#include "ambf_like/step_guard.hpp"
#include "ambf_like/world.hpp"
#include "fuzz_file.hpp"

namespace {

constexpr int kSteps = 20;  ///< enough for contacts, joint limits and soft bodies to act

/// Five tetrahedra filling a 1 cm cube (legacy VTK).
constexpr std::string_view kTetMesh =
    "# vtk DataFile Version 2.0\ncube\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 8 double\n"
    "0 0 0\n0.01 0 0\n0 0.01 0\n0.01 0.01 0\n0 0 0.01\n0.01 0 0.01\n0 0.01 0.01\n0.01 0.01 0.01\n"
    "CELLS 5 25\n4 0 1 2 4\n4 1 3 2 7\n4 1 5 4 7\n4 2 4 6 7\n4 1 2 4 7\nCELL_TYPES 5\n"
    "10\n10\n10\n10\n10\n";

/// The scene a fuzzed world file is tried under: a board, a box on a hinge, a soft cube.
constexpr std::string_view kScene = R"(bodies: [BODY board, BODY box]
joints: [JOINT hinge]
soft bodies: [BODY cube]
BODY board:
  name: board
  mass: 0
  collision shape: BOX
  collision geometry: {x: 0.3, y: 0.3, z: 0.02}
BODY box:
  name: box
  mass: 0.05
  collision shape: BOX
  collision geometry: {x: 0.02, y: 0.02, z: 0.02}
  location: {position: {x: 0.05, y: 0, z: 0.03}}
JOINT hinge:
  name: hinge
  parent: BODY board
  child: BODY box
  parent pivot: {x: 0.05, y: 0, z: 0.03}
  parent axis: {x: 1, y: 0, z: 0}
  child axis: {x: 1, y: 0, z: 0}
  type: revolute
  joint limits: {low: -0.5, high: 0.5}
BODY cube:
  name: cube
  mesh: tet.vtk
  material: {young's modulus: 1e6, poisson's ratio: 0.45, density: 1100}
  location: {position: {x: -0.05, y: 0, z: 0.0105}}
  collision margin: 0.0005
)";

/// The scene's file, written once with the mesh it names beside it.
const std::filesystem::path& sceneFile() {
  static const std::filesystem::path file = [] {
    fuzz::asFile(kTetMesh, "tet.vtk");
    return fuzz::asFile(kScene, "scene.yaml");
  }();
  return file;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const bool world_mode = (data[0] & 1) != 0;
  const auto file = fuzz::asFile(data + 1, size - 1, world_mode ? "world.yaml" : "model.yaml");
  ambf_like::LoadedScene scene;
  try {
    scene = world_mode ? ambf_like::loadModelFiles({sceneFile()}, file)
                       : ambf_like::loadModelFiles({file});
  } catch (const ambf_like::LoadError&) {
    return 0;
  }
  ambf_like::MeshLibrary meshes;
  try {
    ambf_like::World world(scene.spec, meshes);
    world.step(kSteps);
  } catch (const ambf_like::SimulationDiverged&) {
  }
  return 0;
}
