#pragma once
// Reads AMBF launch, world and multibody (ADF) files, and URDF files, into a SceneSpec.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "ambf_like/load_error.hpp"
#include "ambf_like/load_options.hpp"
#include "ambf_like/scene_spec.hpp"

namespace ambf_like {

/// Which multibody files of a launch file to load (AMBF's `-l` and `-a`).
struct LaunchSelection {
  std::vector<int> indices;                        ///< empty: every entry of `multibody configs`
  std::vector<std::filesystem::path> extra_files;  ///< loaded after the selected entries
};

/// The result of a successful load: the scene and the warnings met on the way.
struct LoadedScene {
  SceneSpec spec;
  std::vector<LoadIssue> warnings;
};

/// Parses AMBF's `-l` value, e.g. "0,3". Throws std::invalid_argument naming the bad item.
std::vector<int> parseLaunchIndices(const std::string& text);

/// Loads a launch file: its world file and the selected multibody files. Throws LoadError.
LoadedScene loadLaunchFile(const std::filesystem::path& launch_file,
                           const LaunchSelection& selection, const LoadOptions& options = {});

/// Loads model files (ADF `.yaml` or `.urdf`) into a scene with the given world file, or AMBF's
/// default world when none is given. Throws LoadError.
LoadedScene loadModelFiles(const std::vector<std::filesystem::path>& model_files,
                           const std::optional<std::filesystem::path>& world_file = std::nullopt,
                           const LoadOptions& options = {});

/// Reads model files and adds them after the models of `scene` (their sensors and actuators may
/// name a body of those by its qualified name as parent). Returns the warnings; throws
/// LoadError, leaving `scene` as it was.
std::vector<LoadIssue> appendModelFiles(SceneSpec& scene,
                                        const std::vector<std::filesystem::path>& model_files,
                                        const LoadOptions& options = {});

}  // namespace ambf_like
