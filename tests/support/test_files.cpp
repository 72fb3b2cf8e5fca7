#include "test_files.hpp"

#include <fstream>
#include <iterator>
#include <sstream>
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
                                     const WorldSettings& settings,
                                     ambf_like::WorldOptions options) {
  auto sim = std::make_unique<Simulation>();
  sim->scene = ambf_like::loadModelFiles(model_files);
  if (settings) settings(sim->scene.spec.world);
  sim->world = std::make_unique<ambf_like::World>(sim->scene.spec, sim->meshes, options);
  return sim;
}

std::string boxVtk(int nx, int ny, int nz, double cell) {
  auto index = [&](int i, int j, int k) { return (k * (ny + 1) + j) * (nx + 1) + i; };
  std::ostringstream s;
  const int points = (nx + 1) * (ny + 1) * (nz + 1);
  const int cells = nx * ny * nz * 6;
  s << "# vtk DataFile Version 2.0\nbox\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS " << points
    << " double\n";
  for (int k = 0; k <= nz; ++k) {
    for (int j = 0; j <= ny; ++j) {
      for (int i = 0; i <= nx; ++i) s << i * cell << ' ' << j * cell << ' ' << k * cell << '\n';
    }
  }
  s << "CELLS " << cells << ' ' << cells * 5 << '\n';
  const int around[6][2] = {{1, 3}, {1, 5}, {2, 3}, {2, 6}, {4, 5}, {4, 6}};
  for (int k = 0; k < nz; ++k) {
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i < nx; ++i) {
        auto corner = [&](int bits) {
          return index(i + (bits & 1), j + ((bits >> 1) & 1), k + ((bits >> 2) & 1));
        };
        for (const auto& t : around) {
          s << "4 " << corner(0) << ' ' << corner(t[0]) << ' ' << corner(t[1]) << ' ' << corner(7)
            << '\n';
        }
      }
    }
  }
  s << "CELL_TYPES " << cells << '\n';
  for (int c = 0; c < cells; ++c) s << "10\n";
  return s.str();
}

}  // namespace test_support
