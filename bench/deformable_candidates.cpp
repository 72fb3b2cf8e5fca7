// deformable_candidates: Bullet 3.24's own deformable pipeline (btDeformableMultiBodyDynamicsWorld
// with its stable Neo-Hookean force) measured as a candidate for soft bodies with a material
// (issue 25, docs/soft-materials.md). A 10 mm cube of a Neo-Hookean solid (nu 0.45) between two
// bonded plates is pressed 10 % over 0.1 s and held to 0.3 s, at steps of 0.5, 1 and 2 ms, for
// several moduli and damping coefficients, with the elastic forces explicit (Bullet's default)
// and implicit. Printed: the force on the top plate at the end, whether every node stayed
// finite, how far the free nodes a third of the way up moved (a tenth of a third of 10 mm if the
// cube were squeezed evenly), and the cost of a step on this machine.

#include <BulletSoftBody/btDeformableBodySolver.h>
#include <BulletSoftBody/btDeformableMultiBodyConstraintSolver.h>
#include <BulletSoftBody/btDeformableMultiBodyDynamicsWorld.h>
#include <BulletSoftBody/btDeformableNeoHookeanForce.h>
#include <BulletSoftBody/btSoftBodyRigidBodyCollisionConfiguration.h>
#include <btBulletDynamicsCommon.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

namespace {

constexpr double kSide = 0.01;  // m
constexpr double kPoisson = 0.45;
constexpr double kDensity = 1100.0;  // kg/m^3
constexpr int kCells = 3;            // per side: 64 nodes, 162 tetrahedra
constexpr double kStrain = 0.10;

/// The cube's nodes on a grid and six tetrahedra per cell around its main diagonal.
struct CubeMesh {
  std::vector<btVector3> nodes;
  std::vector<std::array<int, 4>> tetrahedra;
};

double signedVolume(const CubeMesh& mesh, const std::array<int, 4>& t) {
  const btVector3& o = mesh.nodes[static_cast<std::size_t>(t[0])];
  return (mesh.nodes[static_cast<std::size_t>(t[1])] - o)
             .cross(mesh.nodes[static_cast<std::size_t>(t[2])] - o)
             .dot(mesh.nodes[static_cast<std::size_t>(t[3])] - o) /
         6.0;
}

CubeMesh cubeMesh() {
  CubeMesh mesh;
  constexpr int n = kCells + 1;
  auto id = [](int i, int j, int k) { return i + n * (j + n * k); };
  for (int k = 0; k < n; ++k) {
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i)
        mesh.nodes.emplace_back(kSide * i / kCells, kSide * j / kCells, kSide * k / kCells);
    }
  }
  constexpr int kAround[6][2] = {{1, 3}, {3, 2}, {2, 6}, {6, 4}, {4, 5}, {5, 1}};
  for (int k = 0; k < kCells; ++k) {
    for (int j = 0; j < kCells; ++j) {
      for (int i = 0; i < kCells; ++i) {
        const int corner[8] = {id(i, j, k),         id(i + 1, j, k),        id(i, j + 1, k),
                               id(i + 1, j + 1, k), id(i, j, k + 1),        id(i + 1, j, k + 1),
                               id(i, j + 1, k + 1), id(i + 1, j + 1, k + 1)};
        for (const auto& pair : kAround) {
          std::array<int, 4> t{corner[0], corner[pair[0]], corner[pair[1]], corner[7]};
          if (signedVolume(mesh, t) < 0.0) std::swap(t[1], t[2]);
          mesh.tetrahedra.push_back(t);
        }
      }
    }
  }
  return mesh;
}

/// One run's settings and outcome.
struct Case {
  double modulus;  ///< Pa
  double
      damping;  ///< Bullet's coefficient: the damping stiffness is this times the elastic one (s)
  double step;  ///< s
  bool implicit;
};
struct Outcome {
  double force = 0.0;     ///< N, the solid pushing the top plate up
  double interior = 0.0;  ///< m, how far the free nodes at a third of the height moved down
  bool finite = true;
  double us_per_step = 0.0;
};

Outcome press(const Case& c) {
  btSoftBodyRigidBodyCollisionConfiguration config;
  btCollisionDispatcher dispatcher(&config);
  btDbvtBroadphase broadphase;
  btDeformableBodySolver deformable_solver;
  btDeformableMultiBodyConstraintSolver solver;
  solver.setDeformableSolver(&deformable_solver);
  btDeformableMultiBodyDynamicsWorld world(&dispatcher, &broadphase, &solver, &config,
                                           &deformable_solver);
  world.setGravity(btVector3(0, 0, 0));
  world.getWorldInfo().m_gravity.setZero();
  world.setImplicit(c.implicit);
  deformable_solver.setImplicit(c.implicit);

  const CubeMesh mesh = cubeMesh();
  const std::vector<btScalar> unit_masses(mesh.nodes.size(), 1.0);
  auto body =
      std::make_unique<btSoftBody>(&world.getWorldInfo(), static_cast<int>(mesh.nodes.size()),
                                   mesh.nodes.data(), unit_masses.data());
  for (const auto& t : mesh.tetrahedra) body->appendTetra(t[0], t[1], t[2], t[3]);
  body->m_tetraScratches.resize(body->m_tetras.size());
  body->m_tetraScratchesTn.resize(body->m_tetras.size());
  std::vector<double> lumped(mesh.nodes.size(), 0.0);
  for (const auto& t : mesh.tetrahedra) {
    for (int v : t) lumped[static_cast<std::size_t>(v)] += kDensity * signedVolume(mesh, t) / 4.0;
  }
  std::vector<int> top;
  for (std::size_t i = 0; i < mesh.nodes.size(); ++i) {
    const double z = mesh.nodes[i].z();
    const bool on_bottom = z<1e-9, on_top = z> kSide - 1e-9;
    body->setMass(static_cast<int>(i), on_bottom || on_top ? 0.0 : lumped[i]);  // bonded plates
    if (on_top) top.push_back(static_cast<int>(i));
  }
  body->initializeDmInverse();
  body->m_cfg.collisions = 0;
  // Smith et al.'s parameters for Lame's mu and lambda: small strains then answer with E and nu.
  const double mu = c.modulus / (2.0 * (1.0 + kPoisson));
  const double lambda = c.modulus * kPoisson / ((1.0 + kPoisson) * (1.0 - 2.0 * kPoisson));
  btDeformableNeoHookeanForce neo_hookean(4.0 / 3.0 * mu, lambda + 5.0 / 6.0 * mu, c.damping);
  world.addSoftBody(body.get());
  world.addForce(body.get(), &neo_hookean);

  constexpr double kPressTime = 0.1, kEnd = 0.3;
  const auto steps = static_cast<int>(std::lround(kEnd / c.step));
  Outcome out;
  const auto start = std::chrono::steady_clock::now();
  int ran = 0;
  for (int s = 1; s <= steps && out.finite; ++s, ++ran) {
    const double dz = -kSide * kStrain * std::min(1.0, s * c.step / kPressTime);
    for (int i : top) {
      btSoftBody::Node& node = body->m_nodes[i];
      node.m_x.setZ(kSide + dz);
      node.m_q = node.m_x;
      node.m_v.setZero();
    }
    world.stepSimulation(c.step, 0, c.step);
    for (int i = 0; i < body->m_nodes.size(); ++i) {
      const btVector3& x = body->m_nodes[i].m_x;
      if (!std::isfinite(x.x()) || !std::isfinite(x.y()) || !std::isfinite(x.z()) ||
          x.length() > 1.0)
        out.finite = false;
    }
  }
  out.us_per_step =
      std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count() /
      ran;
  if (out.finite) {
    body->updateDeformation();
    btAlignedObjectArray<btVector3> forces;
    forces.resize(body->m_nodes.size());
    for (int i = 0; i < forces.size(); ++i) forces[i].setZero();
    neo_hookean.addScaledElasticForce(1.0, forces);
    for (int i : top) out.force += forces[i].z();
    int third = 0;
    for (std::size_t i = 0; i < mesh.nodes.size(); ++i) {
      if (std::abs(mesh.nodes[i].z() - kSide / 3.0) > 1e-9) continue;
      out.interior += mesh.nodes[i].z() - body->m_nodes[static_cast<int>(i)].m_x.z();
      ++third;
    }
    out.interior /= third;
  }
  world.removeSoftBody(body.get());
  return out;
}

}  // namespace

int main() {
  std::printf(
      "Bullet 3.24 deformable pipeline: 10 mm cube (64 nodes, 162 tetrahedra), nu 0.45, bonded "
      "plates,\npressed 10 %% in 0.1 s and held to 0.3 s; force on the top plate at 0.3 s; the "
      "free "
      "nodes a third of the way up\nmove 333 um if the cube is squeezed evenly\n\n");
  std::printf(
      "| E (Pa) | damping (s) | step (ms) | elastic forces | force (N) | free nodes moved (um) | "
      "us per step |\n|---|---|---|---|---|---|---|\n");
  for (const double modulus : {1e5, 1e6}) {
    for (const double damping : {0.0, 0.001, 0.01}) {
      for (const double step : {0.0005, 0.001, 0.002}) {
        for (const bool implicit : {false, true}) {
          const Outcome o = press({modulus, damping, step, implicit});
          const char* kind = implicit ? "implicit" : "explicit";
          if (o.finite) {
            std::printf("| %.0e | %g | %.1f | %s | %.4f | %.1f | %.0f |\n", modulus, damping,
                        step * 1e3, kind, o.force, o.interior * 1e6, o.us_per_step);
          } else {
            std::printf("| %.0e | %g | %.1f | %s | not finite | - | %.0f |\n", modulus, damping,
                        step * 1e3, kind, o.us_per_step);
          }
        }
      }
    }
  }
}
