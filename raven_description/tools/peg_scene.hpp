#pragma once
// The peg-transfer scene: a board with twelve posts (six in each arm's reach) and six tall soft
// rings resting on the start posts.

#include <filesystem>

#include "raven/design/peg_scene_design.hpp"

namespace raven::model {

using design::PegSceneDesign;

/// Writes peg_board.yaml, rings.yaml and meshes/ring.vtk into `dir`.
void writePegScene(const PegSceneDesign& design, const std::filesystem::path& dir);

}  // namespace raven::model
