#pragma once
// Test helpers: a private temporary directory for generated model files, and where the shared
// reference data lives.

#include <filesystem>
#include <string>

#include "ambf_like/scene_loader.hpp"
#include "ambf_like/world.hpp"

namespace test_support {

/// A fresh directory under the system temp dir, removed when the object goes away.
class TempDir {
 public:
  TempDir();
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  const std::filesystem::path& path() const { return path_; }
  /// Writes `text` to `name` inside the directory and returns its full path.
  std::filesystem::path write(const std::string& name, const std::string& text) const;

 private:
  std::filesystem::path path_;
};

/// The whole content of a text file.
std::string readFile(const std::filesystem::path& file);

/// ../shared/data (next to the repository), or empty when that folder is absent.
std::filesystem::path sharedDataDir();

/// The bundled unit icosphere (162 vertices) used for soft bodies.
std::filesystem::path icosphereMesh();

/// A loaded scene and the World built from it, kept together.
struct Simulation {
  ambf_like::LoadedScene scene;
  ambf_like::MeshLibrary meshes;
  std::unique_ptr<ambf_like::World> world;
};

/// Loads model files (default world) and builds a World; throws what the loader throws.
std::unique_ptr<Simulation> simulate(const std::vector<std::filesystem::path>& model_files,
                                     ambf_like::WorldOptions options = {});

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
