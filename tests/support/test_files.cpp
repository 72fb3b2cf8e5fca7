#include "test_files.hpp"

#include <fstream>
#include <iterator>
#include <stdexcept>

namespace test_support {

std::string readFile(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + file.string());
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::filesystem::path sharedDataDir() {
  const std::filesystem::path dir = RAVEN_SHARED_DATA_DIR;
  return std::filesystem::is_directory(dir) ? dir : std::filesystem::path();
}

std::filesystem::path icosphereMesh() {
  return std::filesystem::path(AMBF_LIKE_EXAMPLES_DIR) / "demo" / "icosphere.obj";
}

std::filesystem::path exampleFile(const std::string& name) {
  return std::filesystem::path(AMBF_LIKE_EXAMPLES_DIR) / name;
}

std::string groundPlaneBody() {
  return "BODY ground:\n"
         "  name: ground\n"
         "  mass: 0\n"
         "  collision shape: PLANE\n"
         "  collision geometry: {normal: {x: 0, y: 0, z: 1}, offset: 0}\n";
}

std::string softBallBody(double margin) {
  return "BODY blob:\n"
         "  name: blob\n"
         "  mass: 0.05\n"
         "  mesh: " +
         icosphereMesh().string() +
         "\n"
         "  scale: 0.05\n"
         "  collision margin: " +
         std::to_string(margin) + "\n";
}

std::unique_ptr<Simulation> simulate(const std::vector<std::filesystem::path>& model_files,
                                     ambf_like::WorldOptions options) {
  auto sim = std::make_unique<Simulation>();
  sim->scene = ambf_like::loadModelFiles(model_files);
  sim->world = std::make_unique<ambf_like::World>(sim->scene.spec, sim->meshes, options);
  return sim;
}

}  // namespace test_support
