#include "urdf_reader.hpp"

#include <console_bridge/console.h>
#include <urdf_parser/urdf_parser.h>

#include <Eigen/Eigenvalues>
#include <fstream>
#include <sstream>
#include <unordered_map>

#include "common/farthest.hpp"
#include "common/file_problem.hpp"
#include "common/utf8.hpp"
#include "common/xml_nesting.hpp"
#include "inertia_check.hpp"
#include "urdf_lines.hpp"

namespace ambf_like::detail {

namespace {

/// Collects urdfdom's console messages so a parse failure can say why.
class CapturedConsole : public console_bridge::OutputHandler {
 public:
  CapturedConsole() : previous_(console_bridge::getOutputHandler()) {
    console_bridge::useOutputHandler(this);
  }
  ~CapturedConsole() override { console_bridge::useOutputHandler(previous_); }
  CapturedConsole(const CapturedConsole&) = delete;
  CapturedConsole& operator=(const CapturedConsole&) = delete;

  void log(const std::string& text, console_bridge::LogLevel level, const char*, int) override {
    if (level >= console_bridge::CONSOLE_BRIDGE_LOG_WARN)
      messages_ += (messages_.empty() ? "" : "; ") + text;
    errors_ = errors_ || level >= console_bridge::CONSOLE_BRIDGE_LOG_ERROR;
  }
  const std::string& messages() const { return messages_; }
  /// Whether urdfdom reported an error: it then may still return a model, with the element it
  /// could not read left out or half read (a link whose mass did not parse has none).
  bool errors() const { return errors_; }

 private:
  console_bridge::OutputHandler* previous_;
  std::string messages_;
  bool errors_ = false;
};

Vec3 toVec(const urdf::Vector3& v) {
  return Vec3(v.x, v.y, v.z);
}

struct UrdfContext {
  std::filesystem::path file;
  LoadContext& load;
  const UrdfLines& lines;
  SourceRef at(const std::string& path) const { return SourceRef{file, lines.lineOf(path), path}; }
  [[noreturn]] void fail(const std::string& path, const std::string& message) const {
    throw LoadError(at(path), message);
  }
};

/// An <origin>'s transform; refused (naming `path`) when its position is not finite or lies
/// beyond common::kFarthestCoordinate, or its rotation is not finite.
Transform toTransform(const urdf::Pose& pose, const std::string& path, const UrdfContext& ctx) {
  Transform t = Transform::Identity();
  const auto& r = pose.rotation;
  const Quat rotation(r.w, r.x, r.y, r.z);
  if (!rotation.coeffs().allFinite() || rotation.norm() == 0.0) {
    ctx.fail(path + "/origin", "rpy is not finite");
  }
  t.linear() = rotation.normalized().toRotationMatrix();
  t.translation() = Vec3(pose.position.x, pose.position.y, pose.position.z);
  if (!t.translation().allFinite() ||
      t.translation().cwiseAbs().maxCoeff() > common::kFarthestCoordinate) {
    ctx.fail(path + "/origin", "xyz is not finite or lies beyond +-1e5 m of the origin");
  }
  return t;
}

std::filesystem::path resolveMeshFile(const std::string& filename, const std::string& path,
                                      const UrdfContext& ctx) {
  std::string name = filename;
  if (name.rfind("package://", 0) == 0) {
    ctx.fail(path, "mesh '" + filename +
                       "' uses package://, which needs a ROS package path; use a path relative "
                       "to the URDF file");
  }
  if (name.rfind("file://", 0) == 0) name = name.substr(7);
  const auto resolved = (ctx.file.parent_path() / name).lexically_normal();
  if (const auto problem = common::fileProblem(resolved); !problem.empty()) {
    if (!ctx.load.options().strict) {
      ctx.load.warn(ctx.at(path),
                    "mesh file " + resolved.string() + ": " + problem + "; continuing without it");
      return {};
    }
    ctx.fail(path, "mesh file " + resolved.string() + ": " + problem);
  }
  return resolved;
}

/// Refuses (naming `path`) a primitive's dimensions unless each is above zero and within
/// common::kFarthestCoordinate: urdfdom takes any number, and Bullet a negative or zero extent.
void requireSize(const Vec3& dimensions, const std::string& path, const UrdfContext& ctx) {
  if (!(dimensions.array() > 0.0).all() ||
      !(dimensions.array() <= common::kFarthestCoordinate).all()) {
    std::ostringstream text;
    text << "each dimension must be greater than zero and at most " << common::kFarthestCoordinate
         << " m (got " << dimensions.transpose() << ")";
    ctx.fail(path, text.str());
  }
}

/// Converts one URDF geometry into a primitive (or, for meshes, a mesh path in `mesh`).
std::optional<PrimitiveShape> readGeometry(const urdf::Geometry& geometry, const urdf::Pose& origin,
                                           const std::string& path, const UrdfContext& ctx,
                                           std::filesystem::path& mesh) {
  PrimitiveShape shape;
  shape.offset = toTransform(origin, path, ctx);
  switch (geometry.type) {
    case urdf::Geometry::BOX:
      shape.type = PrimitiveType::Box;
      shape.box_size = toVec(static_cast<const urdf::Box&>(geometry).dim);
      requireSize(shape.box_size, path + "/box size", ctx);
      return shape;
    case urdf::Geometry::SPHERE:
      shape.type = PrimitiveType::Sphere;
      shape.radius = static_cast<const urdf::Sphere&>(geometry).radius;
      requireSize(Vec3::Constant(shape.radius), path + "/sphere radius", ctx);
      return shape;
    case urdf::Geometry::CYLINDER: {
      const auto& cylinder = static_cast<const urdf::Cylinder&>(geometry);
      shape.type = PrimitiveType::Cylinder;
      shape.radius = cylinder.radius;
      shape.height = cylinder.length;
      requireSize(Vec3(shape.radius, shape.radius, shape.height), path + "/cylinder", ctx);
      return shape;
    }
    case urdf::Geometry::MESH: {
      const auto& m = static_cast<const urdf::Mesh&>(geometry);
      if ((toVec(m.scale) - Vec3::Ones()).norm() > 1e-12) {
        ctx.fail(path, "scaled meshes are not supported");
      }
      if (!shape.offset->isApprox(Transform::Identity())) {
        ctx.fail(path, "a mesh with an origin offset is not supported; bake it into the mesh");
      }
      mesh = resolveMeshFile(m.filename, path, ctx);
      return std::nullopt;
    }
  }
  ctx.fail(path, "unknown geometry type");
}

void readInertial(const urdf::Link& link, bool is_root, BodySpec& body, const UrdfContext& ctx) {
  const std::string path = "link[" + link.name + "]/inertial";
  if (!link.inertial) {
    if (!is_root) ctx.fail(path, "a movable link needs an <inertial> element");
    body.mass = 0.0;  // the root link without inertia is the fixed base
    return;
  }
  const auto& in = *link.inertial;
  if (!(in.mass >= 0.0)) ctx.fail(path, "mass must be a non-negative number");
  body.mass = in.mass;
  Eigen::Matrix3d tensor;
  tensor << in.ixx, in.ixy, in.ixz, in.ixy, in.iyy, in.iyz, in.ixz, in.iyz, in.izz;
  if (!tensor.allFinite()) ctx.fail(path, "inertia must be finite");
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(tensor);
  Eigen::Matrix3d axes = solver.eigenvectors();
  if (axes.determinant() < 0.0) axes.col(2) = -axes.col(2);
  Transform offset = toTransform(in.origin, path, ctx);
  offset.linear() = offset.linear() * axes;
  body.inertial_offset = offset;
  body.inertia = solver.eigenvalues();
  if (in.mass > 0.0 && (body.inertia->array() <= 0.0).any()) {
    ctx.fail(path, "a link with mass needs a positive definite inertia (a principal moment is " +
                       std::to_string(body.inertia->minCoeff()) + ")");
  }
  if (const auto why = impossibleInertia(*body.inertia); in.mass > 0.0 && why) {
    ctx.fail(path, *why);
  }
}

BodySpec readLink(const urdf::Link& link, bool is_root, const Transform& location,
                  const UrdfContext& ctx) {
  BodySpec body;
  body.name = link.name;
  body.location = location;
  body.where = ctx.at("link[" + link.name + "]");
  readInertial(link, is_root, body, ctx);

  for (std::size_t i = 0; i < link.collision_array.size(); ++i) {
    const auto& collision = *link.collision_array[i];
    const std::string path = "link[" + link.name + "]/collision[" + std::to_string(i) + "]";
    if (!collision.geometry) ctx.fail(path, "collision without geometry");
    std::filesystem::path mesh;
    auto primitive = readGeometry(*collision.geometry, collision.origin, path, ctx, mesh);
    if (primitive) body.collision.primitives.push_back(*primitive);
    if (!mesh.empty()) {
      if (!body.collision.mesh.empty())
        ctx.fail(path, "only one collision mesh per link is supported");
      body.collision.mesh = mesh;
    }
  }
  if (!body.collision.mesh.empty() && !body.collision.primitives.empty()) {
    ctx.fail("link[" + link.name + "]", "mixing a collision mesh with primitives is not supported");
  }
  for (std::size_t i = 0; i < link.visual_array.size(); ++i) {
    const auto& visual = *link.visual_array[i];
    if (!visual.geometry) continue;
    const std::string path = "link[" + link.name + "]/visual[" + std::to_string(i) + "]";
    std::filesystem::path mesh;
    auto primitive = readGeometry(*visual.geometry, visual.origin, path, ctx, mesh);
    if (primitive) body.visual_primitives.push_back(*primitive);
    if (!mesh.empty() && body.visual_mesh.empty()) body.visual_mesh = mesh;
  }
  if (body.mass > 0.0 && !body.inertia && body.collision.empty()) {
    ctx.fail("link[" + link.name + "]", "needs an inertia or collision geometry");
  }
  return body;
}

JointSpec readUrdfJoint(const urdf::Joint& joint, const UrdfContext& ctx) {
  const std::string path = "joint[" + joint.name + "]";
  JointSpec spec;
  spec.name = joint.name;
  spec.parent = joint.parent_link_name;
  spec.child = joint.child_link_name;
  spec.where = ctx.at(path);
  const Transform origin = toTransform(joint.parent_to_joint_origin_transform, path, ctx);
  Vec3 axis = toVec(joint.axis);
  // urdfdom gives a joint without <axis> URDF's default, (1, 0, 0), and a fixed joint none.
  if (axis.norm() < 1e-12) {
    if (joint.type != urdf::Joint::FIXED) ctx.fail(path + "/axis", "axis must not be zero");
    axis = Vec3::UnitX();
  }
  spec.parent_pivot = origin.translation();
  spec.parent_axis = (origin.linear() * axis).normalized();
  spec.child_pivot = Vec3::Zero();
  spec.child_axis = axis.normalized();
  switch (joint.type) {
    case urdf::Joint::REVOLUTE:
      spec.type = JointType::Revolute;
      break;
    case urdf::Joint::CONTINUOUS:
      spec.type = JointType::Continuous;
      break;
    case urdf::Joint::PRISMATIC:
      spec.type = JointType::Prismatic;
      break;
    case urdf::Joint::FIXED:
      spec.type = JointType::Fixed;
      break;
    default:
      ctx.fail(path, "joint type is not supported (only revolute, continuous, prismatic, fixed)");
  }
  if ((spec.type == JointType::Revolute || spec.type == JointType::Prismatic) && joint.limits) {
    if (joint.limits->lower > joint.limits->upper) ctx.fail(path + "/limit", "lower > upper");
    spec.limits = JointLimits{joint.limits->lower, joint.limits->upper};
  }
  if (joint.dynamics) spec.damping = joint.dynamics->damping;
  if (joint.mimic)
    ctx.load.warn(ctx.at(path + "/mimic"), "mimic joints are not supported; ignored");
  return spec;
}

}  // namespace

ModelSpec readUrdfModel(const std::filesystem::path& file, LoadContext& context) {
  if (const auto problem = common::fileProblem(file); !problem.empty()) {
    throw LoadError(SourceRef{file, 0, ""}, problem);
  }
  std::ifstream in(file);
  if (!in) throw LoadError(SourceRef{file, 0, ""}, "cannot read file");
  std::stringstream text;
  text << in.rdbuf();
  // urdfdom's XML parser recurses once per element level until the stack ends.
  if (const auto line = common::xmlNestedBeyond(text.str(), common::kMostXmlNesting)) {
    throw LoadError(SourceRef{file, static_cast<int>(*line), ""},
                    "elements nested deeper than " + std::to_string(common::kMostXmlNesting) +
                        " levels; no robot description nests so deep");
  }

  if (const auto line = common::firstMalformedUtf8Line(text.str())) {
    throw LoadError(SourceRef{file, static_cast<int>(*line), ""},
                    "not well-formed UTF-8 (XML requires it): a malformed byte sequence or a NUL");
  }

  const UrdfLines lines(file, text.str());
  const UrdfContext ctx{file, context, lines};
  urdf::ModelInterfaceSharedPtr urdf;
  std::string messages;
  bool parse_errors = false;
  {
    CapturedConsole console;
    urdf = urdf::parseURDF(text.str());
    messages = console.messages();
    parse_errors = console.errors();
  }
  if (!urdf || parse_errors) {
    throw LoadError(SourceRef{file, lines.lineNamedIn(messages), ""},
                    "not a valid URDF" + (messages.empty() ? "" : ": " + messages));
  }

  ModelSpec model;
  model.file = file;
  model.name_space = "/ambf/env/" + urdf->getName() + "/";
  // Depth-first from the root so every link's location follows from its parent's.
  std::vector<std::pair<urdf::LinkConstSharedPtr, Transform>> pending{
      {urdf->getRoot(), Transform::Identity()}};
  // urdfdom keeps the last of two joints naming one child and lists both under their parents:
  // read as they are, a loop of joints would be walked round until its links left the world.
  std::unordered_map<std::string, std::string> joint_above;  // child link -> its joint
  while (!pending.empty()) {
    auto [link, location] = pending.back();
    pending.pop_back();
    model.bodies.push_back(readLink(*link, link == urdf->getRoot(), location, ctx));
    for (const auto& joint : link->child_joints) {
      if (const auto [seen, first] = joint_above.try_emplace(joint->child_link_name, joint->name);
          !first) {
        ctx.fail("joint[" + joint->name + "]", "makes link[" + joint->child_link_name +
                                                   "] the child of a second joint (after joint[" +
                                                   seen->second + "]): a URDF's links form a tree");
      }
      model.joints.push_back(readUrdfJoint(*joint, ctx));
      const auto child = urdf->getLink(joint->child_link_name);
      const Transform placed = location * toTransform(joint->parent_to_joint_origin_transform,
                                                      "joint[" + joint->name + "]", ctx);
      if (placed.translation().cwiseAbs().maxCoeff() > common::kFarthestCoordinate) {
        ctx.fail("link[" + joint->child_link_name + "]",
                 "its joints place it beyond +-1e5 m of the origin");
      }
      pending.emplace_back(child, placed);
    }
  }
  return model;
}

}  // namespace ambf_like::detail
