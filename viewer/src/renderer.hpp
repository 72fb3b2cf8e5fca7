#pragma once
// Draws a SceneGeometry at a FrameState with OpenGL 2.1 (fixed function: any Mesa works, llvmpipe
// included), into whatever context is current.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "viewer/camera.hpp"
#include "viewer/camera_sensor.hpp"
#include "viewer/look.hpp"
#include "viewer/scene_geometry.hpp"
#include "viewer/viewer.hpp"

namespace viewer::detail {

void draw(const SceneGeometry& scene, const FrameState& frame, const Camera& camera, int width,
          int height, const ViewOptions& view, const Look& look = {});

/// The scene with every surface in the flat colour of its segmentation id (id = r + 256 g +
/// 65536 b; the background 0), no lighting.
void drawLabels(const SceneGeometry& scene, const FrameState& frame, const Camera& camera,
                int width, int height, const SceneLabels& labels);

/// The current depth buffer as distances along the camera's axis (m), top row first; where
/// nothing was drawn, +infinity.
std::vector<float> readDepth(const Camera& camera, int width, int height);

/// A line of text in the top left corner, over whatever is drawn (the window's status line).
void overlay(const std::string& text, int width, int height);

/// The current framebuffer as RGB rows, top row first.
std::vector<std::uint8_t> readPixels(int width, int height);
/// The current framebuffer as RGBA rows as OpenGL keeps them, bottom row first (a video
/// frame: the encoder's converter flips it for free).
void readPixelsRgba(int width, int height, std::vector<std::uint8_t>& rgba);

/// Throws std::runtime_error naming the file if it cannot be written.
void writePng(const std::filesystem::path& file, const std::vector<std::uint8_t>& rgb, int width,
              int height);

}  // namespace viewer::detail
