#pragma once
// The viewer tests' scene: the shipped peg-transfer scene with its rings settled, and a headless
// viewer on it (none, with EGL's reason, on a machine without headless OpenGL).

#include <memory>
#include <string>

#include "ambf_like/scene_loader.hpp"
#include "ambf_like/world.hpp"
#include "test_files.hpp"
#include "viewer/viewer.hpp"

namespace test_support {

/// The peg-transfer scene after 200 steps, seen by a width x height headless viewer.
struct HeadlessPegScene {
  static constexpr int kWidth = 640, kHeight = 400;
  ambf_like::MeshLibrary meshes;
  std::unique_ptr<ambf_like::World> world;
  std::unique_ptr<viewer::Viewer> view;
  TempDir dir;
  std::string why;  ///< without a viewer: what EGL said

  HeadlessPegScene() {
    const auto scene = ambf_like::loadLaunchFile(
        std::filesystem::path(RAVEN_MODELS_DIR) / "peg_transfer/launch.yaml", {});
    world = std::make_unique<ambf_like::World>(scene.spec, meshes);
    world->step(200);
    viewer::ViewerOptions options;
    options.window = false;
    options.width = kWidth;
    options.height = kHeight;
    try {
      view = std::make_unique<viewer::Viewer>(*world, options);
    } catch (const viewer::NoDisplay& e) {
      why = e.what();
    }
  }
};

}  // namespace test_support
