#include "soft_body_factory.hpp"

#include <BulletSoftBody/btSoftBody.h>
#include <BulletSoftBody/btSoftBodyHelpers.h>

#include <cmath>
#include <set>

#include "ambf_like/dynamics/soft_body_step_solver.hpp"

namespace ambf_like::detail {

namespace {

void applyConfig(const SoftBodyConfig& c, btSoftBody& body) {
  auto& cfg = body.m_cfg;
  cfg.kVCF = c.kVCF;
  cfg.kDP = c.kDP;
  cfg.kDG = c.kDG;
  cfg.kLF = c.kLF;
  cfg.kPR = c.kPR;
  cfg.kVC = c.kVC;
  cfg.kDF = c.kDF;
  cfg.kMT = c.kMT;
  cfg.kCHR = c.kCHR;
  cfg.kKHR = c.kKHR;
  cfg.kSHR = c.kSHR;
  cfg.kAHR = c.kAHR;
  cfg.kSRHR_CL = c.kSRHR_CL;
  cfg.kSKHR_CL = c.kSKHR_CL;
  cfg.kSSHR_CL = c.kSSHR_CL;
  cfg.kSR_SPLT_CL = c.kSR_SPLT_CL;
  cfg.kSK_SPLT_CL = c.kSK_SPLT_CL;
  cfg.kSS_SPLT_CL = c.kSS_SPLT_CL;
  cfg.maxvolume = c.maxvolume;
  cfg.timescale = c.timescale;
  cfg.viterations = c.viterations;
  cfg.piterations = c.piterations;
  cfg.diterations = c.diterations;
  cfg.citerations = c.citerations;
  cfg.collisions = c.collision_flags;
  auto* material = body.m_materials[0];
  material->m_kLST = c.kLST;
  material->m_kAST = c.kAST;
  material->m_kVST = c.kVST;
}

/// A surface mesh's body: a node per vertex, a link per triangle edge (Bullet's own helper).
std::unique_ptr<btSoftBody> surfaceBody(const SoftBodySpec& spec, const Mesh& mesh,
                                        const std::vector<btScalar>& vertices,
                                        btSoftBodyWorldInfo& world_info) {
  std::vector<int> triangles;
  triangles.reserve(mesh.triangles.size() * 3);
  for (const auto& t : mesh.triangles) triangles.insert(triangles.end(), t.begin(), t.end());
  return std::unique_ptr<btSoftBody>(btSoftBodyHelpers::CreateFromTriMesh(
      world_info, vertices.data(), triangles.data(), static_cast<int>(mesh.triangles.size()),
      spec.randomize_constraints));
}

/// A volume mesh's body: a node per vertex, a link per tetrahedron edge (so the body resists
/// being squeezed through its thickness, not only stretched along its surface), the boundary
/// faces (contact, volume, drawing) and the tetrahedra (mass by volume).
std::unique_ptr<btSoftBody> volumeBody(const Mesh& mesh, const std::vector<btScalar>& vertices,
                                       btSoftBodyWorldInfo& world_info) {
  std::vector<btVector3> nodes;
  for (std::size_t i = 0; i < vertices.size(); i += 3) {
    nodes.emplace_back(vertices[i], vertices[i + 1], vertices[i + 2]);
  }
  auto body = std::make_unique<btSoftBody>(&world_info, static_cast<int>(nodes.size()),
                                           nodes.data(), nullptr);
  std::set<std::pair<int, int>> edges;
  for (const auto& t : mesh.tetrahedra) {
    for (int a = 0; a < 4; ++a) {
      for (int b = a + 1; b < 4; ++b) edges.emplace(std::minmax(t[a], t[b]));
    }
    body->appendTetra(t[0], t[1], t[2], t[3]);
  }
  for (const auto& [a, b] : edges) body->appendLink(a, b, nullptr, false);
  for (const auto& f : mesh.triangles) body->appendFace(f[0], f[1], f[2]);
  return body;
}

/// The body's volume at rest: Bullet keeps each tetrahedron's as six times it (m_rv, the triple
/// product of its edges).
double volumeOf(const btSoftBody& body) {
  double six_times = 0.0;
  for (int i = 0; i < body.m_tetras.size(); ++i) six_times += std::abs(body.m_tetras[i].m_rv);
  return six_times / 6.0;
}

/// Each node carries a quarter of every tetrahedron it is a corner of (a lumped mass matrix),
/// scaled to `mass` in all.
void setLumpedMasses(btSoftBody& body, double mass) {
  std::vector<double> share(static_cast<std::size_t>(body.m_nodes.size()), 0.0);
  double volume = 0.0;
  for (int i = 0; i < body.m_tetras.size(); ++i) {
    const btSoftBody::Tetra& t = body.m_tetras[i];
    for (const btSoftBody::Node* n : t.m_n) {
      share[static_cast<std::size_t>(n - &body.m_nodes[0])] += std::abs(t.m_rv) / 4.0;
    }
    volume += std::abs(t.m_rv);
  }
  for (int i = 0; i < body.m_nodes.size(); ++i) {
    body.setMass(i, mass * share[static_cast<std::size_t>(i)] / volume);
  }
}

}  // namespace

std::unique_ptr<btSoftBody> makeSoftBody(const SoftBodySpec& spec, const Mesh& mesh,
                                         btSoftBodyWorldInfo& world_info) {
  std::vector<btScalar> vertices;
  vertices.reserve(mesh.vertices.size() * 3);
  for (const auto& v : mesh.vertices) {
    const Vec3 p = spec.location * (v * spec.scale);
    vertices.insert(vertices.end(), {p.x(), p.y(), p.z()});
  }
  const bool solid = !mesh.tetrahedra.empty();
  if (spec.material && !solid) {
    SourceRef where = spec.where;
    where.key_path += "/material";
    throw LoadError(where, "soft body '" + spec.name +
                               "': a material needs a volume (tetrahedral) mesh; '" +
                               spec.mesh.filename().string() + "' is a surface");
  }
  std::unique_ptr<btSoftBody> body = solid ? volumeBody(mesh, vertices, world_info)
                                           : surfaceBody(spec, mesh, vertices, world_info);

  const auto& c = spec.config;
  applyConfig(c, *body);
  if (c.bending_constraint > 0) body->generateBendingConstraints(c.bending_constraint);
  if (solid) {
    const bool by_density = spec.material && spec.material->density > 0.0;
    setLumpedMasses(*body, by_density ? spec.material->density * volumeOf(*body) : spec.mass);
  } else {
    body->setTotalMass(spec.mass, true);
  }
  if (c.kVC > 0.0 || c.kMT > 0.0) body->setPose(c.kVC > 0.0, c.kMT > 0.0);
  for (int index : c.fixed_nodes) {
    if (index >= body->m_nodes.size()) {
      SourceRef where = spec.where;
      where.key_path += "/config/fixed nodes";
      throw LoadError(where, "fixed node " + std::to_string(index) +
                                 " does not exist (soft body '" + spec.name + "' has " +
                                 std::to_string(body->m_nodes.size()) + " nodes)");
    }
    body->setMass(index, 0.0);
  }
  if (c.clusters > 0) body->generateClusters(c.clusters);
  // AMBF shuffles last, its bending links with the rest (a surface body's mesh links were
  // shuffled once already as Bullet's helper made them). In mesh order, a node's bending links
  // follow one another, and each waits for the one before it to move their shared node: 1.5x
  // slower on AMBF's cloth.
  if (spec.randomize_constraints) body->randomizeConstraints();
  // Bodies with a material find contacts a band beyond their margin (kCoulombContactBand).
  const double detection = spec.margin + (spec.material ? kCoulombContactBand : 0.0);
  body->getCollisionShape()->setMargin(detection);
  // Bullet sized each node's bounding-volume leaf with the default 0.25 m margin when it made the
  // node, and later only grows a leaf that no longer holds its node: refit them to the real
  // margin, or every rigid body within 25 cm tests every node at every step. A body that touches
  // no rigid body keeps Bullet's (and AMBF's) fat leaves: a tree that no rigid body asks is
  // rebuilt less often as its nodes move (about 9 % of AMBF's cloth's step).
  if (c.collision_flags & btSoftBody::fCollision::RVSmask) {
    for (int i = 0; i < body->m_nodes.size(); ++i) {
      btSoftBody::Node& node = body->m_nodes[i];
      btDbvtVolume volume = btDbvtVolume::FromCR(node.m_x, detection);
      body->m_ndbvt.update(node.m_leaf, volume);
    }
  }
  body->updateBounds();
  return body;
}

}  // namespace ambf_like::detail
