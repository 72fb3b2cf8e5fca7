#pragma once
// A camera as a sensor: colour, depth (m along the camera's axis) and segmentation images of a
// World from a View, rendered headless (EGL) on the calling thread, for observations.

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <vector>

#include "ambf_like/world.hpp"
#include "viewer/look.hpp"
#include "viewer/view.hpp"

namespace viewer {

struct SceneGeometry;
namespace detail {
class HeadlessContext;
}

/// Segmentation ids of a scene's surfaces (0 is the background): per rigid body one id, or one
/// per triangle of its visual mesh (a board whose posts are told apart); per soft body one id.
struct SceneLabels {
  std::vector<std::vector<std::uint32_t>> bodies;  ///< World body order
  std::vector<std::uint32_t> soft_bodies;          ///< World soft-body order
};

/// One rendering.
struct CameraImages {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;            ///< rows top first, 3 bytes a pixel
  std::vector<float> depth;                 ///< m along the axis; +infinity where nothing is
  std::vector<std::uint32_t> segmentation;  ///< the SceneLabels id seen at each pixel
};

/// Renders a World's views at one size. Throws viewer::NoDisplay when no headless OpenGL can be
/// made, std::invalid_argument for a size outside 8..4096.
class CameraSensor {
 public:
  /// `label` says how the scene's surfaces (as drawn) segment; `skin`: visual meshes (empty: the
  /// bodies' own).
  CameraSensor(const ambf_like::World& world, int width, int height,
               const std::function<SceneLabels(const SceneGeometry&)>& label,
               const std::filesystem::path& skin = {});
  ~CameraSensor();
  CameraSensor(const CameraSensor&) = delete;
  CameraSensor& operator=(const CameraSensor&) = delete;

  /// The images `view` sees of `world` now (only those asked for are filled), the colour image
  /// drawn with `look`.
  CameraImages render(const ambf_like::World& world, const View& view, bool rgb, bool depth,
                      bool segmentation, const Look& look = {});

 private:
  int width_, height_;
  SceneLabels labels_;
  std::unique_ptr<const SceneGeometry> geometry_;
  std::unique_ptr<detail::HeadlessContext> context_;
};

}  // namespace viewer
