#include "viewer/visual_skin.hpp"

#include <cstdlib>

#include "common/yaml_view.hpp"

namespace viewer {

VisualSkin VisualSkin::load(const std::filesystem::path& file) {
  const common::YamlView root = common::YamlView::parseFile(file);
  std::vector<common::LoadIssue> no_warnings;  // strict: an unknown key is an error
  const common::KeyCheck strict{true, no_warnings};
  root.checkKeys({"mesh path", "bodies"}, strict);
  VisualSkin skin;
  skin.file = file;
  const char* override_dir = std::getenv("RAVEN_AMBF_MESHES");
  skin.mesh_dir = override_dir && *override_dir ? std::filesystem::path(override_dir)
                                                : file.parent_path() / root["mesh path"].asString();
  const common::YamlView bodies = root["bodies"];
  for (const std::string& body : bodies.keys()) {
    const common::YamlView piece = bodies[body];
    piece.checkKeys({"mesh", "offset"}, strict);
    skin.bodies[body] = {piece["mesh"].asString(), piece["offset"].asPose()};
  }
  return skin;
}

const VisualSkin::Piece* VisualSkin::find(const std::string& body) const {
  const auto it = bodies.find(body);
  return it == bodies.end() ? nullptr : &it->second;
}

std::filesystem::path VisualSkin::firstMissing() const {
  for (const auto& [body, piece] : bodies) {
    if (!std::filesystem::is_regular_file(mesh_dir / piece.mesh)) return mesh_dir / piece.mesh;
  }
  return {};
}

}  // namespace viewer
