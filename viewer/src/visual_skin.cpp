#include "viewer/visual_skin.hpp"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <cstdlib>
#include <stdexcept>

#include "ambf_like/transform.hpp"

namespace viewer {

namespace {

std::runtime_error bad(const std::filesystem::path& file, const YAML::Node& node,
                       const std::string& what) {
  return std::runtime_error(fmt::format("{}:{}: {}", file.string(), node.Mark().line + 1, what));
}

double number(const std::filesystem::path& file, const YAML::Node& map, const char* key) {
  const YAML::Node value = map[key];
  if (!value) throw bad(file, map, fmt::format("missing key '{}'", key));
  try {
    return value.as<double>();
  } catch (const YAML::Exception&) {
    throw bad(file, value, fmt::format("'{}' is not a number", key));
  }
}

Eigen::Isometry3d pose(const std::filesystem::path& file, const YAML::Node& offset) {
  if (!offset || !offset.IsMap()) throw bad(file, offset, "'offset' must be a map");
  const YAML::Node p = offset["position"], o = offset["orientation"];
  if (!p || !o) throw bad(file, offset, "'offset' needs 'position' and 'orientation'");
  return ambf_like::makeTransform(
      {number(file, p, "x"), number(file, p, "y"), number(file, p, "z")},
      {number(file, o, "r"), number(file, o, "p"), number(file, o, "y")});
}

}  // namespace

VisualSkin VisualSkin::load(const std::filesystem::path& file) {
  YAML::Node root;
  try {
    root = YAML::LoadFile(file.string());
  } catch (const YAML::BadFile&) {
    throw std::runtime_error(file.string() + ": file not found");
  } catch (const YAML::ParserException& e) {
    throw std::runtime_error(fmt::format("{}:{}: {}", file.string(), e.mark.line + 1, e.msg));
  }
  VisualSkin skin;
  skin.file = file;
  const YAML::Node path = root["mesh path"], bodies = root["bodies"];
  if (!path) throw bad(file, root, "missing key 'mesh path'");
  if (!bodies || !bodies.IsMap()) throw bad(file, root, "'bodies' must be a map");
  const char* override_dir = std::getenv("RAVEN_AMBF_MESHES");
  skin.mesh_dir = override_dir && *override_dir ? std::filesystem::path(override_dir)
                                                : file.parent_path() / path.as<std::string>();
  for (const auto& entry : bodies) {
    const YAML::Node piece = entry.second;
    if (!piece.IsMap() || !piece["mesh"]) throw bad(file, piece, "a body needs 'mesh'");
    for (const auto& key : piece) {
      const auto name = key.first.as<std::string>();
      if (name != "mesh" && name != "offset")
        throw bad(file, key.first, "unknown key '" + name + "'");
    }
    skin.bodies[entry.first.as<std::string>()] = {piece["mesh"].as<std::string>(),
                                                  pose(file, piece["offset"])};
  }
  return skin;
}

std::filesystem::path VisualSkin::firstMissing() const {
  for (const auto& [body, piece] : bodies) {
    if (!std::filesystem::is_regular_file(mesh_dir / piece.mesh)) return mesh_dir / piece.mesh;
  }
  return {};
}

}  // namespace viewer
