#include <sstream>

#include "adf_readers.hpp"
#include "inertia_check.hpp"

namespace ambf_like::detail {

namespace {

/// AMBF falls back to its default, a concave mesh, for a type it does not know (the surgical
/// robotics challenge's psm1.yaml leaves it empty): a warning, an error under --strict.
CollisionMeshType readMeshType(const YamlView& node, LoadContext& context) {
  const auto text = node.asKeyword();
  if (text == "concave_mesh" || text == "trimesh") return CollisionMeshType::ConcaveMesh;
  if (text == "convex_mesh") return CollisionMeshType::ConvexMesh;
  if (text == "convex_hull") return CollisionMeshType::ConvexHull;
  if (text == "point_cloud") return CollisionMeshType::PointCloud;
  context.tolerate(node.where(),
                   "unknown collision mesh type '" + node.asString() +
                       "' (expected CONCAVE_MESH, TRIMESH, CONVEX_MESH, CONVEX_HULL or "
                       "POINT_CLOUD); AMBF's default, CONCAVE_MESH, is used");
  return CollisionMeshType::ConcaveMesh;
}

/// A value in [0, `maximum`]: beyond it the body is no longer a physical one this simulator can
/// step (Bullet's sums overflow or lose every digit).
double nonNegative(const YamlView& node, double maximum, const char* unit) {
  const double value = node.asDouble();
  if (value < 0.0) node.fail("must not be negative (got " + std::to_string(value) + ")");
  if (value > maximum) {
    std::ostringstream range;
    range << "must be at most " << maximum << unit << " (got " << value << ")";
    node.fail(range.str());
  }
  return value;
}

void reportMissing(const SourceRef& where, const std::string& message, LoadContext& context) {
  context.tolerate(where, message + "; continuing without it");
}

std::vector<PrimitiveShape> readCollisionPrimitives(const YamlView& node, LoadContext& context) {
  const bool compound = node.has("compound collision shape");
  if (compound && node.has("collision shape")) {
    node["collision shape"].fail("give either 'collision shape' or 'compound collision shape'");
  }
  if (compound) return readCompoundShape(node["compound collision shape"], context);
  if (!node.has("collision shape")) return {};
  std::optional<Transform> offset;
  if (auto o = node.find("collision offset")) offset = o->asPose();
  return {readPrimitive(node["collision shape"], node["collision geometry"], offset)};
}

std::vector<PrimitiveShape> readVisualPrimitives(const YamlView& node, LoadContext& context) {
  if (auto list = node.find("compound shape")) return readCompoundShape(*list, context);
  if (auto shape = node.find("shape"))
    return {readPrimitive(*shape, node["geometry"], std::nullopt)};
  return {};
}

/// Every rigid-body key of ADF 1.0. Accepted but not simulated: publishing, colours, shaders,
/// plugins and the body's Cartesian controller (this simulator commands joints); `visible` only
/// decides whether views draw the body.
// clang-format off
constexpr std::string_view kBodyKeys[] = {
    "name", "namespace", "mesh", "collision mesh", "collision mesh type", "shape", "geometry",
    "compound shape", "collision shape", "collision geometry", "collision offset",
    "compound collision shape", "mass", "inertia", "inertial offset", "location", "scale",
    "collision margin", "collision groups", "friction", "restitution", "damping", "controller",
    "passive", "publish frequency", "publish joint names", "publish joint positions",
    "publish children names", "color", "color rgba", "color components", "visible", "shaders",
    "plugins", "gravity", "high resolution path", "low resolution path", "use material",
    "redundant", "detached"};
// clang-format on

/// The body's mass, inertia, frames, scale, gravity, passivity and visibility.
void readMassAndPlacement(const YamlView& node, BodySpec& body, LoadContext& context) {
  if (auto mass = node.find("mass")) {
    body.mass = nonNegative(*mass, 1e6, " kg");
  } else {  // AMBF warns and leaves the body's mass at its default: static
    context.tolerate(node.where(), "body '" + body.name +
                                       "': missing required key 'mass' (AMBF warns and loads "
                                       "such a body static, mass 0)");
    body.mass = 0.0;
  }
  if (auto inertia = node.find("inertia")) {
    body.inertia = Vec3(nonNegative((*inertia)["ix"], 1e6, " kg m^2"),
                        nonNegative((*inertia)["iy"], 1e6, " kg m^2"),
                        nonNegative((*inertia)["iz"], 1e6, " kg m^2"));
    // Bullet takes a zero moment as an axis that never turns, which its joints then tear at.
    if (body.mass > 0.0 && (body.inertia->array() <= 0.0).any()) {
      inertia->fail("a body with mass needs every principal moment (ix, iy, iz) above zero");
    }
    if (const auto why = impossibleInertia(*body.inertia); body.mass > 0.0 && why) {
      inertia->fail(*why);
    }
  }
  if (auto offset = node.find("inertial offset")) body.inertial_offset = offset->asPose();
  if (auto location = node.find("location")) body.location = location->asPose();
  if (auto scale = node.find("scale")) {
    body.scale = scale->asDouble();
    if (!(body.scale >= 1e-6 && body.scale <= 1e6)) scale->fail("scale must be 1e-6 to 1e6");
  }
  if (auto gravity = node.find("gravity")) body.gravity = gravity->asXyz();
  body.passive = node.getBool("passive", false);
  body.visible = node.getBool("visible", true);
}

/// Friction, damping and restitution.
void readSurface(const YamlView& node, BodySpec& body, LoadContext& context) {
  if (auto friction = node.find("friction")) {
    friction->checkKeys({"static", "rolling"}, context.keyCheck());
    if (auto v = friction->find("static"))
      body.surface.static_friction = nonNegative(*v, 100.0, "");
    if (auto v = friction->find("rolling"))
      body.surface.rolling_friction = nonNegative(*v, 100.0, "");
  }
  if (auto damping = node.find("damping")) {
    damping->checkKeys({"linear", "angular"}, context.keyCheck());
    if (auto v = damping->find("linear"))
      body.surface.linear_damping = nonNegative(*v, 1.0, " (a fraction per second)");
    if (auto v = damping->find("angular"))
      body.surface.angular_damping = nonNegative(*v, 1.0, " (a fraction per second)");
  }
  if (auto restitution = node.find("restitution")) {
    body.surface.restitution = nonNegative(*restitution, 1.0, "");
  }
}

/// The collision margin and groups, and the collision and visual primitives.
void readCollisionSettings(const YamlView& node, BodySpec& body, LoadContext& context) {
  auto& collision = body.collision;
  if (auto margin = node.find("collision margin"))
    collision.margin = nonNegative(*margin, 1.0, " m");
  if (auto groups = node.find("collision groups")) {
    for (const auto& group : groups->elements()) {
      const int value = group.asInt();
      if (value < 0 || value > 999) group.fail("collision group must be in 0..999");
      collision.groups.push_back(value);
    }
  }
  collision.primitives = readCollisionPrimitives(node, context);
  body.visual_primitives = readVisualPrimitives(node, context);
}

/// Finds the visual and collision meshes in `local`'s folders, reporting the missing ones;
/// returns whether the body's collision geometry was to come from a mesh that is missing.
bool findMeshes(const YamlView& node, const MeshDirectories& local, BodySpec& body,
                LoadContext& context) {
  auto& collision = body.collision;
  const std::string mesh_name = node.has("mesh") ? node["mesh"].asString() : "";
  if (node.has("mesh") && mesh_name.empty()) {
    context.tolerate(node["mesh"].where(), "an empty mesh name: the body has no mesh");
  }
  const std::string collision_name =
      node.has("collision mesh") ? node["collision mesh"].asString() : mesh_name;
  if (auto type = node.find("collision mesh type"))
    collision.mesh_type = readMeshType(*type, context);

  const bool wants_collision_mesh = collision.primitives.empty() && !collision_name.empty();
  std::string tried_visual, tried_collision;
  std::optional<std::filesystem::path> visual, collision_mesh;
  if (!mesh_name.empty()) visual = findMesh(mesh_name, {local.high_res}, tried_visual);
  if (wants_collision_mesh) {
    collision_mesh = findMesh(collision_name, {local.low_res, local.high_res}, tried_collision);
  }
  const std::string body_label = "body '" + body.name + "': ";
  if (wants_collision_mesh && !collision_mesh && !visual && collision_name == mesh_name) {
    reportMissing(
        node["mesh"].where(),
        body_label + "mesh file '" + mesh_name + "' not found (looked for " + tried_collision + ")",
        context);
  } else {
    if (!mesh_name.empty() && !visual) {
      reportMissing(node["mesh"].where(),
                    body_label + "visual mesh '" + mesh_name + "' not found (looked for " +
                        tried_visual + ")",
                    context);
    }
    if (wants_collision_mesh && !collision_mesh) {
      const auto key = node.has("collision mesh") ? node["collision mesh"] : node["mesh"];
      reportMissing(key.where(),
                    body_label + "collision mesh '" + collision_name + "' not found (looked for " +
                        tried_collision + ")",
                    context);
    }
  }
  if (visual) body.visual_mesh = *visual;
  if (collision_mesh) collision.mesh = *collision_mesh;
  return wants_collision_mesh && !collision_mesh;
}

/// A dynamic body left without inertia gets a solid sphere's (AMBF computes it from the collision
/// shape, which it lacks); a plane must be static.
void checkDynamics(const YamlView& node, bool missing_geometry, BodySpec& body,
                   LoadContext& context) {
  const std::string body_label = "body '" + body.name + "': ";
  if (body.mass > 0.0 && !body.inertia && (body.collision.empty() || missing_geometry)) {
    const double r = kFallbackInertiaRadius;
    body.inertia = Vec3::Constant(0.4 * body.mass * r * r);
    context.tolerate(node["mass"].where(),
                     body_label +
                         (missing_geometry ? "its inertia was to come from the missing mesh"
                                           : "a dynamic body without collision geometry or "
                                             "'inertia'") +
                         "; using a solid sphere's of its mass and " + std::to_string(r) +
                         " m radius (give 'inertia' to set it)");
  }
  for (const auto& primitive : body.collision.primitives) {
    if (primitive.type == PrimitiveType::Plane && body.mass > 0.0) {
      node["mass"].fail(body_label + "a PLANE collision shape needs a static body (mass 0)");
    }
  }
}

}  // namespace

BodySpec readBody(const YamlView& node, const std::string& identifier, const MeshDirectories& dirs,
                  LoadContext& context) {
  node.checkKeys(kBodyKeys, context.keyCheck());
  noteNotSimulated(node, context);
  BodySpec body;
  body.where = node.where();
  body.name = node.has("name") ? node["name"].asString() : stripPrefix(identifier);
  if (body.name.empty()) node["name"].fail("body name is empty");
  const MeshDirectories local = meshDirectoriesOf(node, dirs);
  readMassAndPlacement(node, body, context);
  readSurface(node, body, context);
  readCollisionSettings(node, body, context);
  const bool missing_geometry = findMeshes(node, local, body, context);
  checkDynamics(node, missing_geometry, body, context);
  return body;
}

}  // namespace ambf_like::detail
