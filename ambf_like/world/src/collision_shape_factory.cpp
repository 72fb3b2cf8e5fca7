#include "collision_shape_factory.hpp"

#include <BulletCollision/CollisionShapes/btBoxShape.h>
#include <BulletCollision/CollisionShapes/btBvhTriangleMeshShape.h>
#include <BulletCollision/CollisionShapes/btCapsuleShape.h>
#include <BulletCollision/CollisionShapes/btCompoundShape.h>
#include <BulletCollision/CollisionShapes/btConeShape.h>
#include <BulletCollision/CollisionShapes/btConvexHullShape.h>
#include <BulletCollision/CollisionShapes/btConvexTriangleMeshShape.h>
#include <BulletCollision/CollisionShapes/btCylinderShape.h>
#include <BulletCollision/CollisionShapes/btSphereShape.h>
#include <BulletCollision/CollisionShapes/btStaticPlaneShape.h>
#include <BulletCollision/CollisionShapes/btTriangleIndexVertexArray.h>
#include <BulletCollision/Gimpact/btGImpactShape.h>

#include <algorithm>

#include "ambf_like/bullet_conversions.hpp"

namespace ambf_like::detail {

struct ShapeStore::Buffers {
  std::vector<btScalar> vertices;
  std::vector<int> indices;
  std::unique_ptr<btTriangleIndexVertexArray> array;
};

ShapeStore::ShapeStore() = default;
ShapeStore::~ShapeStore() = default;

btCollisionShape* ShapeStore::keep(std::unique_ptr<btCollisionShape> shape) {
  shapes_.push_back(std::move(shape));
  return shapes_.back().get();
}

btTriangleIndexVertexArray* ShapeStore::meshInterface(const Mesh& mesh, double scale,
                                                      const Transform& transform) {
  auto buffers = std::make_unique<Buffers>();
  buffers->vertices.reserve(mesh.vertices.size() * 3);
  for (const auto& v : mesh.vertices) {
    const Vec3 p = transform * (v * scale);
    buffers->vertices.insert(buffers->vertices.end(), {p.x(), p.y(), p.z()});
  }
  buffers->indices.reserve(mesh.triangles.size() * 3);
  for (const auto& t : mesh.triangles)
    buffers->indices.insert(buffers->indices.end(), t.begin(), t.end());
  buffers->array = std::make_unique<btTriangleIndexVertexArray>(
      static_cast<int>(mesh.triangles.size()), buffers->indices.data(), 3 * sizeof(int),
      static_cast<int>(mesh.vertices.size()), buffers->vertices.data(), 3 * sizeof(btScalar));
  buffers_.push_back(std::move(buffers));
  return buffers_.back()->array.get();
}

namespace {

std::unique_ptr<btCollisionShape> makeConvexPrimitive(const PrimitiveShape& p, double scale) {
  const double r = p.radius * scale;
  const double h = p.height * scale;
  switch (p.type) {
    case PrimitiveType::Box:
      return std::make_unique<btBoxShape>(toBt(p.box_size * scale * 0.5));
    case PrimitiveType::Sphere:
      return std::make_unique<btSphereShape>(r);
    case PrimitiveType::Cylinder:
      switch (p.axis) {
        case Axis::X:
          return std::make_unique<btCylinderShapeX>(btVector3(h / 2, r, r));
        case Axis::Y:
          return std::make_unique<btCylinderShape>(btVector3(r, h / 2, r));
        case Axis::Z:
          return std::make_unique<btCylinderShapeZ>(btVector3(r, r, h / 2));
      }
      break;
    case PrimitiveType::Capsule:
      switch (p.axis) {
        case Axis::X:
          return std::make_unique<btCapsuleShapeX>(r, h);
        case Axis::Y:
          return std::make_unique<btCapsuleShape>(r, h);
        case Axis::Z:
          return std::make_unique<btCapsuleShapeZ>(r, h);
      }
      break;
    case PrimitiveType::Cone:
      switch (p.axis) {
        case Axis::X:
          return std::make_unique<btConeShapeX>(r, h);
        case Axis::Y:
          return std::make_unique<btConeShape>(r, h);
        case Axis::Z:
          return std::make_unique<btConeShapeZ>(r, h);
      }
      break;
    case PrimitiveType::Plane:
      break;  // not convex: see makePrimitive
  }
  return nullptr;
}

/// Half size of the box that realises a PLANE for soft bodies (and moving bodies). Bullet's soft
/// bodies cannot rest on a btStaticPlaneShape (soft-vs-concave contact goes through temporary
/// triangles and its sparse SDF: they float or fall through), so there a plane is the top face
/// of a convex 1 km box.
constexpr double kPlaneHalfSize = 500.0;

/// The primitive's shape and where it sits relative to the primitive's own frame; a plane as a
/// half-space or as the top of a box.
std::pair<std::unique_ptr<btCollisionShape>, Transform> makePrimitive(const PrimitiveShape& p,
                                                                      double scale,
                                                                      bool plane_as_half_space) {
  if (p.type == PrimitiveType::Plane && plane_as_half_space) {
    return {std::make_unique<btStaticPlaneShape>(toBt(p.plane_normal.normalized()),
                                                 p.plane_offset * scale),
            Transform::Identity()};
  }
  if (p.type == PrimitiveType::Plane) {
    Transform below = Transform::Identity();
    below.linear() = rotationBetween(Vec3::UnitZ(), p.plane_normal).toRotationMatrix();
    below.translation() = p.plane_normal * (p.plane_offset * scale - kPlaneHalfSize);
    return {std::make_unique<btBoxShape>(btVector3(kPlaneHalfSize, kPlaneHalfSize, kPlaneHalfSize)),
            below};
  }
  return {makeConvexPrimitive(p, scale), Transform::Identity()};
}

btCollisionShape* makeMeshShape(const BodySpec& body, const Mesh& mesh,
                                const Transform& mesh_in_com, ShapeStore& store) {
  const auto& collision = body.collision;
  if (collision.mesh_type == CollisionMeshType::ConvexHull ||
      collision.mesh_type == CollisionMeshType::PointCloud) {
    auto hull = std::make_unique<btConvexHullShape>();
    for (const auto& v : mesh.vertices) hull->addPoint(toBt(mesh_in_com * (v * body.scale)), false);
    hull->recalcLocalAabb();
    hull->optimizeConvexHull();
    return store.keep(std::move(hull));
  }
  auto* triangles = store.meshInterface(mesh, body.scale, mesh_in_com);
  if (collision.mesh_type == CollisionMeshType::ConvexMesh) {
    return store.keep(std::make_unique<btConvexTriangleMeshShape>(triangles));
  }
  if (body.mass == 0.0) {  // static concave geometry: a BVH is far cheaper than GImpact
    return store.keep(std::make_unique<btBvhTriangleMeshShape>(triangles, true));
  }
  return store.keep(std::make_unique<btGImpactMeshShape>(triangles));
}

Transform scaledPose(const Transform& pose, double scale) {
  Transform out = pose;
  out.translation() *= scale;
  return out;
}

/// The body's primitives as one shape in its COM frame: the primitive itself when there is one
/// at the COM, else a compound.
btCollisionShape* primitivesShape(const BodySpec& body, const Transform& body_in_com,
                                  const Transform& com_in_body, bool planes_as_half_spaces,
                                  ShapeStore& store) {
  const auto& collision = body.collision;
  std::vector<std::pair<btCollisionShape*, Transform>> children;
  for (const auto& primitive : collision.primitives) {
    const Transform offset =
        primitive.offset ? scaledPose(*primitive.offset, body.scale) : com_in_body;
    auto [made, local] = makePrimitive(primitive, body.scale, planes_as_half_spaces);
    auto* shape = store.keep(std::move(made));
    shape->setMargin(collision.margin);
    children.emplace_back(shape, body_in_com * offset * local);
  }
  const bool single_at_com =
      children.size() == 1 && children[0].second.isApprox(Transform::Identity());
  if (single_at_com) return children[0].first;
  auto compound = std::make_unique<btCompoundShape>(true, static_cast<int>(children.size()));
  for (const auto& [shape, pose] : children) compound->addChildShape(toBt(pose), shape);
  return store.keep(std::move(compound));
}

}  // namespace

BodyShape buildBodyShape(const BodySpec& body, MeshLibrary& meshes, ShapeStore& store) {
  BodyShape out;
  const auto& collision = body.collision;
  std::shared_ptr<const Mesh> mesh;
  if (!collision.mesh.empty()) {
    SourceRef where = body.where;
    where.key_path += "/collision mesh";
    mesh = meshes.load(collision.mesh, where);
    out.vertex_count = mesh->vertices.size();
  }

  if (body.inertial_offset) {
    out.com_in_body = scaledPose(*body.inertial_offset, body.scale);
  } else if (mesh) {
    out.com_in_body.translation() = mesh->centroid() * body.scale;
  }
  const Transform body_in_com = out.com_in_body.inverse();

  // Mesh shapes are baked into the COM frame; primitives become children of a compound.
  if (mesh) {
    out.shape = makeMeshShape(body, *mesh, body_in_com, store);
  } else if (!collision.primitives.empty()) {
    out.primitive_count = collision.primitives.size();
    const bool has_plane =
        std::any_of(collision.primitives.begin(), collision.primitives.end(),
                    [](const PrimitiveShape& p) { return p.type == PrimitiveType::Plane; });
    const bool half_spaces = has_plane && body.mass == 0.0;
    out.shape = primitivesShape(body, body_in_com, out.com_in_body, half_spaces, store);
    if (half_spaces) {
      out.soft_proxy = primitivesShape(body, body_in_com, out.com_in_body, false, store);
    }
  }
  if (out.soft_proxy != nullptr) out.soft_proxy->setMargin(collision.margin);
  if (out.shape != nullptr) {
    out.shape->setMargin(collision.margin);
    if (auto* gimpact = dynamic_cast<btGImpactShapeInterface*>(out.shape)) gimpact->updateBound();
    // Convex hulls cache their bounding box with the margin they were built with (Bullet's
    // 4 cm default): recompute it, or every hull reaches 4 cm further in the broadphase.
    if (auto* hull = dynamic_cast<btPolyhedralConvexAabbCachingShape*>(out.shape)) {
      hull->recalcLocalAabb();
    }
  }
  if (body.inertia) {
    out.local_inertia = *body.inertia;
  } else if (body.mass > 0.0 && out.shape != nullptr) {
    btVector3 inertia(0, 0, 0);
    out.shape->calculateLocalInertia(body.mass, inertia);
    out.local_inertia = toEigen(inertia);
  }
  return out;
}

}  // namespace ambf_like::detail
