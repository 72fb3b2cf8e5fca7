#include "viewer/scene_geometry.hpp"

#include <BulletSoftBody/btSoftBody.h>
#include <btBulletDynamicsCommon.h>
#include <spdlog/spdlog.h>

#include <functional>

#include "tessellation.hpp"
#include "vertex_clustering.hpp"

namespace viewer {

namespace {

/// A calm palette; a body keeps its colour from run to run (hash of its name).
Eigen::Vector3f colourFor(const std::string& name) {
  static const std::array<Eigen::Vector3f, 6> palette{
      Eigen::Vector3f(0.80f, 0.80f, 0.83f), Eigen::Vector3f(0.55f, 0.65f, 0.80f),
      Eigen::Vector3f(0.75f, 0.72f, 0.60f), Eigen::Vector3f(0.60f, 0.75f, 0.65f),
      Eigen::Vector3f(0.70f, 0.62f, 0.75f), Eigen::Vector3f(0.85f, 0.75f, 0.55f)};
  return palette[std::hash<std::string>{}(name) % palette.size()];
}

/// The centre-of-mass frame in the body frame: where Bullet's collision shape sits, and where an
/// ADF primitive without an offset goes (AMBF's legacy rule, already applied by the loader).
Eigen::Isometry3d comInBody(const ambf_like::RigidBody& body) {
  return body.pose().inverse() * body.centerOfMassPose();
}

TriangleMesh visualOf(const ambf_like::RigidBody& body, ambf_like::MeshLibrary& meshes) {
  const auto& spec = body.spec();
  TriangleMesh m;
  if (!spec.visual_mesh.empty()) {
    const auto mesh = meshes.load(spec.visual_mesh, spec.where);
    for (const auto& t : mesh->triangles) {
      auto v = [&](int i) {
        return Eigen::Vector3f((mesh->vertices[i] * spec.scale).cast<float>());
      };
      m.add(v(t[0]), v(t[1]), v(t[2]));
    }
  }
  for (const auto& p : spec.visual_primitives) {
    Eigen::Isometry3d offset =
        p.offset.value_or(spec.inertial_offset.value_or(ambf_like::Transform::Identity()));
    offset.translation() *= spec.scale;
    m.append(detail::tessellate(p, spec.scale), offset);
  }
  return m;
}

/// Cells along each side of a skin mesh's bounds: a 0.3 m link keeps 1 cm detail, a 15 mm jaw
/// half a millimetre (AMBF's 190,771 Raven triangles become 23,000; docs/viewer.md).
constexpr int kSkinCells = 32;

/// A skin's mesh in the body frame, its vertices clustered for drawing.
TriangleMesh skinOf(const VisualSkin::Piece& piece, const VisualSkin& skin,
                    ambf_like::MeshLibrary& meshes) {
  const auto full = meshes.load(skin.mesh_dir / piece.mesh, {skin.file, 0, piece.mesh.string()});
  const ambf_like::Mesh mesh = detail::clusterVertices(*full, kSkinCells);
  const Eigen::Isometry3f offset = piece.offset.cast<float>();
  TriangleMesh m;
  for (const auto& t : mesh.triangles) {
    auto v = [&](int i) { return Eigen::Vector3f(offset * mesh.vertices[i].cast<float>()); };
    m.add(v(t[0]), v(t[1]), v(t[2]));
  }
  return m;
}

void grow(Eigen::AlignedBox3d& box, const TriangleMesh& m, const Eigen::Isometry3d& pose) {
  Eigen::AlignedBox3f local;
  for (const auto& p : m.positions) local.extend(p);
  if (local.isEmpty() || local.sizes().maxCoeff() > 1.9f) return;  // planes would swamp it
  for (int corner = 0; corner < 8; ++corner) {
    box.extend(pose *
               local.corner(static_cast<Eigen::AlignedBox3f::CornerType>(corner)).cast<double>());
  }
}

}  // namespace

void TriangleMesh::add(const Eigen::Vector3f& a, const Eigen::Vector3f& b,
                       const Eigen::Vector3f& c) {
  Eigen::Vector3f n = (b - a).cross(c - a);
  const float length = n.norm();
  n = length > 0.0f ? Eigen::Vector3f(n / length) : Eigen::Vector3f::UnitZ();
  positions.insert(positions.end(), {a, b, c});
  normals.insert(normals.end(), {n, n, n});
}

void TriangleMesh::append(const TriangleMesh& other, const Eigen::Isometry3d& pose) {
  const Eigen::Isometry3f f = pose.cast<float>();
  for (std::size_t i = 0; i < other.positions.size(); ++i) {
    positions.push_back(f * other.positions[i]);
    normals.push_back(f.linear() * other.normals[i]);
  }
}

SceneGeometry SceneGeometry::of(const ambf_like::World& world,
                                const std::filesystem::path& skin_file) {
  ambf_like::MeshLibrary meshes;
  if (skin_file.empty()) return of(world, meshes);
  const VisualSkin skin = VisualSkin::load(skin_file);
  if (const auto missing = skin.firstMissing(); !missing.empty()) {
    spdlog::info(
        "{}: {} is not there (set RAVEN_AMBF_MESHES to AMBF's raven_2 mesh folder): "
        "drawing the bodies' own shapes",
        skin_file.string(), missing.string());
    return of(world, meshes);
  }
  return of(world, meshes, &skin);
}

SceneGeometry SceneGeometry::of(const ambf_like::World& world, ambf_like::MeshLibrary& meshes,
                                const VisualSkin* skin) {
  SceneGeometry g;
  for (std::size_t i = 0; i < world.bodyCount(); ++i) {
    const auto& body = world.body(i);
    BodyGeometry b;
    b.name = body.qualifiedName();
    b.colour = colourFor(b.name);
    b.collision.append(detail::tessellate(*body.bullet().getCollisionShape()), comInBody(body));
    const VisualSkin::Piece* piece = skin ? skin->find(b.name) : nullptr;
    if (body.spec().visible) {
      b.visual = piece ? skinOf(*piece, *skin, meshes) : visualOf(body, meshes);
      if (b.visual.positions.empty()) b.visual = b.collision;
      grow(g.bounds, b.visual, body.pose());
    }
    g.bodies.push_back(std::move(b));
  }
  for (std::size_t i = 0; i < world.softBodyCount(); ++i) {
    const btSoftBody& soft = world.softBody(i).bullet();
    SoftGeometry s;
    s.name = world.softBody(i).qualifiedName();
    const btSoftBody::Node* first = &soft.m_nodes[0];
    for (int f = 0; f < soft.m_faces.size(); ++f) {
      const auto& face = soft.m_faces[f];
      s.faces.push_back({static_cast<int>(face.m_n[0] - first),
                         static_cast<int>(face.m_n[1] - first),
                         static_cast<int>(face.m_n[2] - first)});
    }
    for (int l = 0; s.faces.empty() && l < soft.m_links.size(); ++l) {
      s.links.push_back({static_cast<int>(soft.m_links[l].m_n[0] - first),
                         static_cast<int>(soft.m_links[l].m_n[1] - first)});
    }
    for (const auto& x : world.softBody(i).nodePositions()) g.bounds.extend(x);
    g.soft_bodies.push_back(std::move(s));
  }
  if (g.bounds.isEmpty())
    g.bounds = Eigen::AlignedBox3d(Eigen::Vector3d::Constant(-0.5), Eigen::Vector3d::Constant(0.5));
  return g;
}

FrameState FrameState::of(const ambf_like::World& world, bool with_contacts) {
  FrameState f;
  f.sim_time = world.time();
  f.steps = world.stepCount();
  f.body_poses.reserve(world.bodyCount());
  for (std::size_t i = 0; i < world.bodyCount(); ++i) f.body_poses.push_back(world.body(i).pose());
  for (std::size_t i = 0; i < world.softBodyCount(); ++i) {
    std::vector<Eigen::Vector3f> nodes;
    for (const auto& x : world.softBody(i).nodePositions()) nodes.push_back(x.cast<float>());
    f.soft_nodes.push_back(std::move(nodes));
  }
  if (with_contacts) f.contacts = world.contacts();
  return f;
}

}  // namespace viewer
