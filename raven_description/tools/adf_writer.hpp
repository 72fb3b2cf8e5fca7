#pragma once
// Writes a drafted model as an ADF file (simplified or dense collision geometry) and its meshes.

#include <filesystem>

#include "model_draft.hpp"

namespace raven::model {

/// Which collision geometry a written model carries.
enum class Collision {
  Simplified,  ///< primitives and small convex hulls (the paper's "after")
  Dense,       ///< the same shapes as dense triangle meshes (the paper's "before")
};

/// Writes `model` to `file`, its meshes to `mesh_dir` (relative paths in the file are relative
/// to the file's folder). Returns the number of collision vertices written.
std::size_t writeModel(const ModelDraft& model, Collision collision,
                       const std::filesystem::path& file, const std::filesystem::path& mesh_dir);

}  // namespace raven::model
