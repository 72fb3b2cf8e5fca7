#pragma once
// Test helpers: generated model files in a private temporary directory, and where the shared
// reference data lives.

#include <filesystem>
#include <functional>
#include <string>

#include "ambf_like/scene_loader.hpp"
#include "ambf_like/world.hpp"
#include "harness/temp_dir.hpp"

namespace test_support {

using harness::TempDir;

/// The whole content of a text file.
std::string readFile(const std::filesystem::path& file);

/// ../shared/data (next to the repository), or empty when that folder is absent.
std::filesystem::path sharedDataDir();

/// The bundled unit icosphere (162 vertices) used for soft bodies.
std::filesystem::path icosphereMesh();
/// A file of ambf_like/examples.
std::filesystem::path exampleFile(const std::string& name);

/// ADF text of a static body "ground": the plane z = 0.
std::string groundPlaneBody();

/// ADF text of a soft ball "blob" of 5 cm radius and 50 g (the icosphere) with `margin`; the
/// caller appends its location and config lines.
std::string softBallBody(double margin);

/// A VTK volume mesh: a box of `nx` x `ny` x `nz` cells of `cell` (m), from the origin up, each
/// cell cut into six tetrahedra around its diagonal (all cells the same way, so neighbours share
/// faces).
std::string boxVtk(int nx, int ny, int nz, double cell);

/// A loaded scene and the World built from it, kept together.
struct Simulation {
  ambf_like::LoadedScene scene;
  ambf_like::MeshLibrary meshes;
  std::unique_ptr<ambf_like::World> world;
};

/// A test's changes to the world file's settings (WorldSpec: sleep, articulation, solver).
using WorldSettings = std::function<void(ambf_like::WorldSpec&)>;

/// Loads model files (default world), changes its settings and builds a World; throws what the
/// loader throws.
std::unique_ptr<Simulation> simulate(const std::vector<std::filesystem::path>& model_files,
                                     const WorldSettings& settings = {},
                                     ambf_like::WorldOptions options = {});

/// The world settings with soft-body sleep off.
inline void noSoftBodySleep(ambf_like::WorldSpec& world) {
  world.soft_body_sleep.enabled = false;
}

/// The world settings with every dynamic rigid body kept awake (AMBF's way).
inline void noRigidBodySleep(ambf_like::WorldSpec& world) {
  world.rigid_body_sleep.enabled = false;
}

/// The world settings with every joint a constraint (AMBF's way).
inline void maximalArticulation(ambf_like::WorldSpec& world) {
  world.articulation = ambf_like::Articulation::Maximal;
}

/// Runs `call` and returns the LoadError message it threw ("" when it did not throw one).
template <typename Call>
std::string loadErrorOf(Call&& call) {
  try {
    call();
  } catch (const ambf_like::LoadError& e) {
    return e.what();
  }
  return "";
}

}  // namespace test_support
