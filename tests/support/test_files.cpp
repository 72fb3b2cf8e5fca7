#include "test_files.hpp"

#include <fstream>
#include <iterator>
#include <random>
#include <stdexcept>

namespace test_support {

TempDir::TempDir() {
  std::random_device seed;
  std::mt19937_64 random(seed());
  path_ = std::filesystem::temp_directory_path() / ("raven_test_" + std::to_string(random()));
  std::filesystem::create_directories(path_);
}

TempDir::~TempDir() {
  std::error_code ignored;
  std::filesystem::remove_all(path_, ignored);
}

std::filesystem::path TempDir::write(const std::string& name, const std::string& text) const {
  const auto file = path_ / name;
  std::filesystem::create_directories(file.parent_path());
  std::ofstream out(file, std::ios::binary);
  out << text;
  if (!out) throw std::runtime_error("cannot write " + file.string());
  return file;
}

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

std::unique_ptr<Simulation> simulate(const std::vector<std::filesystem::path>& model_files,
                                     ambf_like::WorldOptions options) {
  auto sim = std::make_unique<Simulation>();
  sim->scene = ambf_like::loadModelFiles(model_files);
  sim->world = std::make_unique<ambf_like::World>(sim->scene.spec, sim->meshes, options);
  return sim;
}

}  // namespace test_support
