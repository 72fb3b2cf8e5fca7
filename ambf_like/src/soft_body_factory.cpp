#include "soft_body_factory.hpp"

#include <BulletSoftBody/btSoftBody.h>
#include <BulletSoftBody/btSoftBodyHelpers.h>

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

}  // namespace

std::unique_ptr<btSoftBody> makeSoftBody(const SoftBodySpec& spec, const Mesh& mesh,
                                         btSoftBodyWorldInfo& world_info) {
  std::vector<btScalar> vertices;
  vertices.reserve(mesh.vertices.size() * 3);
  for (const auto& v : mesh.vertices) {
    const Vec3 p = spec.location * (v * spec.scale);
    vertices.insert(vertices.end(), {p.x(), p.y(), p.z()});
  }
  std::vector<int> triangles;
  triangles.reserve(mesh.triangles.size() * 3);
  for (const auto& t : mesh.triangles) triangles.insert(triangles.end(), t.begin(), t.end());

  std::unique_ptr<btSoftBody> body(btSoftBodyHelpers::CreateFromTriMesh(
      world_info, vertices.data(), triangles.data(), static_cast<int>(mesh.triangles.size()),
      spec.randomize_constraints));

  const auto& c = spec.config;
  applyConfig(c, *body);
  if (c.bending_constraint > 0) body->generateBendingConstraints(c.bending_constraint);
  body->setTotalMass(spec.mass, true);
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
  body->getCollisionShape()->setMargin(spec.margin);
  // Bullet sized each node's bounding-volume leaf with the default 0.25 m margin when it made the
  // node, and later only grows a leaf that no longer holds its node: refit them to the real
  // margin, or every rigid body within 25 cm tests every node at every step.
  for (int i = 0; i < body->m_nodes.size(); ++i) {
    btSoftBody::Node& node = body->m_nodes[i];
    btDbvtVolume volume = btDbvtVolume::FromCR(node.m_x, spec.margin);
    body->m_ndbvt.update(node.m_leaf, volume);
  }
  body->updateBounds();
  return body;
}

}  // namespace ambf_like::detail
