#pragma once
// What the viewer draws, split as MuJoCo splits model and data: SceneGeometry is built once from a
// World (triangles of every body's visual and collision geometry, soft-body faces); FrameState is
// one instant of it (poses, soft-body nodes, contacts), copied from the physics thread.

#include <Eigen/Geometry>
#include <array>
#include <string>
#include <vector>

#include "ambf_like/mesh.hpp"
#include "ambf_like/world.hpp"
#include "viewer/visual_skin.hpp"

namespace viewer {

/// Flat-shaded triangles: three positions and three (equal) normals per triangle.
struct TriangleMesh {
  std::vector<Eigen::Vector3f> positions;
  std::vector<Eigen::Vector3f> normals;
  void add(const Eigen::Vector3f& a, const Eigen::Vector3f& b, const Eigen::Vector3f& c);
  /// Appends `other` moved by `pose`.
  void append(const TriangleMesh& other, const Eigen::Isometry3d& pose);
  std::size_t triangles() const { return positions.size() / 3; }
};

/// One rigid body's geometry in its body (mesh) frame.
struct BodyGeometry {
  std::string name;
  TriangleMesh visual;     ///< the visual mesh or primitives (the collision geometry if none)
  TriangleMesh collision;  ///< Bullet's collision shape as simulated
  Eigen::Vector3f colour = Eigen::Vector3f::Constant(0.7f);
};

/// One soft body's surface: triangles over its nodes.
struct SoftGeometry {
  std::string name;
  std::vector<std::array<int, 3>> faces;
  std::vector<std::array<int, 2>> links;  ///< drawn when there are no faces
};

/// Immutable drawing data of a World.
struct SceneGeometry {
  std::vector<BodyGeometry> bodies;  ///< in World body order
  std::vector<SoftGeometry> soft_bodies;
  Eigen::AlignedBox3d bounds;  ///< of everything at build time, planes left out

  /// Throws ambf_like::LoadError if a visual mesh cannot be read. A skin's meshes replace the
  /// visuals of the bodies it names.
  static SceneGeometry of(const ambf_like::World& world, ambf_like::MeshLibrary& meshes,
                          const VisualSkin* skin = nullptr);
  /// As above, with the skin file's meshes if they are all there (else the bodies' own visuals,
  /// saying so once in the log); an empty path: no skin.
  static SceneGeometry of(const ambf_like::World& world, const std::filesystem::path& skin_file);
};

/// One instant of the World, as drawn.
struct FrameState {
  std::vector<Eigen::Isometry3d> body_poses;
  std::vector<std::vector<Eigen::Vector3f>> soft_nodes;
  std::vector<ambf_like::Contact> contacts;
  double sim_time = 0.0;
  std::uint64_t steps = 0;

  static FrameState of(const ambf_like::World& world, bool with_contacts);
};

}  // namespace viewer
