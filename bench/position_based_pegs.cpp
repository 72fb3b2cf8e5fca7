#include "position_based_pegs.hpp"

#include <yaml-cpp/yaml.h>

#include <fstream>
#include <stdexcept>

#include "raven/platform_profile.hpp"

namespace bench {

namespace {

void write(const YAML::Node& node, const std::filesystem::path& file) {
  std::ofstream out(file);
  out << node << '\n';
  if (!out) throw std::runtime_error("cannot write " + file.string());
}

}  // namespace

std::filesystem::path writePositionBasedPegScene(const std::filesystem::path& dir) {
  const auto models = raven::modelDirectory();
  const auto shipped = models / "peg_transfer";
  YAML::Node rings = YAML::LoadFile((shipped / "rings.yaml").string());
  const std::string meshes = (shipped / "meshes").string() + "/";
  rings["high resolution path"] = meshes;
  rings["low resolution path"] = meshes;
  for (const auto& entry : rings["soft bodies"]) {
    YAML::Node body = rings[entry.as<std::string>()];
    body.remove("material");
    body["mass"] = 0.002;
    body["contact friction"] = "coulomb";
    body["substeps"] = 4;
    YAML::Node config;
    config["kDF"] = 0.8;
    config["kDP"] = 0.001;
    config["kMT"] = 0.1;
    config["kVC"] = 10.0;
    config["piterations"] = 2;
    config["flags"] = 1;
    body["config"] = config;
  }
  write(rings, dir / "rings.yaml");
  YAML::Node launch;
  launch["world config"] = (shipped / "world.yaml").string();
  for (const auto& file :
       {models / "raven2" / "raven2_left.yaml", models / "raven2" / "raven2_right.yaml",
        shipped / "peg_board.yaml", dir / "rings.yaml"}) {
    launch["multibody configs"].push_back(file.string());
  }
  write(launch, dir / "launch.yaml");
  return dir / "launch.yaml";
}

}  // namespace bench
