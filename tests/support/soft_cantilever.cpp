#include "soft_cantilever.hpp"

#include <BulletSoftBody/btSoftBody.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "test_files.hpp"

namespace test_support {

namespace {

constexpr double kWindow = 0.05;  ///< s

double farthestMove(const std::vector<ambf_like::Vec3>& from,
                    const std::vector<ambf_like::Vec3>& to) {
  double farthest = 0.0;
  for (std::size_t i = 0; i < from.size(); ++i)
    farthest = std::max(farthest, (to[i] - from[i]).norm());
  return farthest;
}

}  // namespace

double CantileverSag::settledAfter(double still) const {
  std::size_t k = window_moves.size();
  while (k > 0 && window_moves[k - 1] < still) --k;
  return kWindow * static_cast<double>(k);
}

CantileverSag settleCantilever(const CantileverSpec& spec) {
  const double cell = spec.width / spec.cells;
  const int along = static_cast<int>(std::lround(spec.length / cell));
  TempDir dir;
  dir.write("beam.vtk", boxVtk(along, spec.cells, spec.cells, cell));
  std::ostringstream fixed;  // the points of the face x = 0, by their index in the file
  for (int k = 0; k <= spec.cells; ++k) {
    for (int j = 0; j <= spec.cells; ++j) {
      fixed << (k || j ? ", " : "") << (k * (spec.cells + 1) + j) * (along + 1);
    }
  }
  std::ostringstream adf;
  adf << "soft bodies: [BODY beam]\nBODY beam:\n  name: beam\n  mesh: beam.vtk\n"
      << "  material: {young's modulus: " << spec.youngs_modulus
      << ", poisson's ratio: " << spec.poisson << ", density: " << spec.density << "}\n"
      << "  location: {position: {x: 0, y: 0, z: 0.5}}\n  collision margin: 0.0001\n"
      << "  substeps: " << spec.substeps << "\n  config: {kDP: " << spec.damping
      << ", fixed nodes: [" << fixed.str() << "]}\n";
  ambf_like::WorldOptions options;
  options.step_size = spec.step;
  const auto keepAwake = [&spec](ambf_like::WorldSpec& world) {
    if (!spec.sleep) noSoftBodySleep(world);
  };
  auto sim = simulate({dir.write("scene.yaml", adf.str())}, keepAwake, options);
  auto& beam = sim->world->softBody("beam");
  const auto rest = beam.nodePositions();
  const auto steps = static_cast<std::uint64_t>(std::lround(spec.duration / spec.step));
  const auto per_window = static_cast<std::uint64_t>(std::lround(kWindow / spec.step));
  CantileverSag sag;
  auto window_start = rest;
  for (std::uint64_t done = 0; done < steps;) {
    const auto now = std::min(per_window, steps - done);
    sim->world->step(now);
    done += now;
    if (now < per_window) break;
    const auto at = beam.nodePositions();
    sag.window_moves.push_back(farthestMove(window_start, at));
    window_start = at;
  }
  sag.finite = beam.isFinite();
  sag.asleep = beam.isAsleep();
  sag.solve = sim->world->elasticSolveStats(beam);
  int count = 0;
  for (std::size_t i = 0; i < rest.size(); ++i) {
    if (rest[i].x() > spec.length - 1e-9) {
      sag.tip_sag += rest[i].z() - beam.nodePosition(i).z();
      ++count;
    }
  }
  sag.tip_sag /= count;
  return sag;
}

}  // namespace test_support
