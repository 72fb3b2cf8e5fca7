#pragma once
// Reads a URDF file (through urdfdom) into the same ModelSpec an ADF file produces.

#include <filesystem>

#include "ambf_like/scene_spec.hpp"
#include "load_context.hpp"

namespace ambf_like::detail {

ModelSpec readUrdfModel(const std::filesystem::path& file, LoadContext& context);

}  // namespace ambf_like::detail
