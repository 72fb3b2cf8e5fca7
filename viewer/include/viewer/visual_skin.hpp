#pragma once
// Meshes drawn in place of some bodies' own visuals: another model's look on our links (AMBF's
// Raven-II meshes on our Raven-II). Drawn only, never used for contact.

#include <Eigen/Geometry>
#include <filesystem>
#include <map>
#include <string>

namespace viewer {

/// A skin file: for each body (by qualified name) a mesh file and its frame in the body frame.
struct VisualSkin {
  /// One body's mesh.
  struct Piece {
    std::filesystem::path mesh;  ///< resolved against mesh_dir
    Eigen::Isometry3d offset = Eigen::Isometry3d::Identity();
  };
  std::map<std::string, Piece> bodies;
  std::filesystem::path file;
  std::filesystem::path mesh_dir;  ///< $RAVEN_AMBF_MESHES, else the file's `mesh path`

  /// Reads a skin file. Throws common::LoadError naming the file, line and key of bad input.
  static VisualSkin load(const std::filesystem::path& file);
  /// The piece drawn on `body` (a qualified name), or null.
  const Piece* find(const std::string& body) const;
  /// The first mesh file that is not there, or empty when all are.
  std::filesystem::path firstMissing() const;
};

}  // namespace viewer
