#include "adf_writer.hpp"

#include <map>
#include <set>
#include <tuple>

#include "raven/control_cycle.hpp"
#include "yaml_out.hpp"

namespace raven::model {

namespace {

using Eigen::Isometry3d;
using Eigen::Vector3d;

/// Segments around round shapes, and subdivisions of the jaw hulls, in the dense variant.
constexpr int kDenseSegments = 64;
constexpr int kDenseJawSubdivisions = 4;

YAML::Node primitive(const Primitive& p, int index) {
  YAML::Node n;
  n["name"] = std::to_string(index);
  YAML::Node g;
  switch (p.type) {
    case Primitive::Type::Box:
      n["shape"] = "BOX";
      g["x"] = number(p.size.x());
      g["y"] = number(p.size.y());
      g["z"] = number(p.size.z());
      break;
    case Primitive::Type::Capsule:
    case Primitive::Type::Cylinder:
      n["shape"] = p.type == Primitive::Type::Capsule ? "CAPSULE" : "CYLINDER";
      g["radius"] = number(p.size.x());
      g["height"] = number(p.size.y());
      g["axis"] = "Z";
      break;
  }
  n["geometry"] = flow(g);
  n["offset"] = pose(p.pose);
  return n;
}

/// Every vertex of the body's geometry in its frame (primitives by their dense tessellation's
/// coarse cousin: enough for a bounding box).
Eigen::AlignedBox3d bounds(const BodyDraft& body) {
  Eigen::AlignedBox3d box;
  for (const auto& p : body.primitives) {
    for (const auto& v : p.tessellate(8).vertices) box.extend(v);
  }
  for (const auto& v : body.hull) box.extend(v);
  return box;
}

/// One midpoint subdivision: each triangle into four (the surface stays where it is).
TriangleMesh subdivide(const TriangleMesh& in) {
  TriangleMesh out;
  out.vertices = in.vertices;
  std::map<std::pair<int, int>, int> midpoint;
  auto mid = [&](int a, int b) {
    const auto key = std::minmax(a, b);
    auto [it, inserted] = midpoint.emplace(key, static_cast<int>(out.vertices.size()));
    if (inserted)
      out.vertices.push_back((in.vertices[std::size_t(a)] + in.vertices[std::size_t(b)]) / 2.0);
    return it->second;
  };
  for (const auto& t : in.triangles) {
    const int ab = mid(t[0], t[1]), bc = mid(t[1], t[2]), ca = mid(t[2], t[0]);
    out.triangles.push_back({t[0], ab, ca});
    out.triangles.push_back({ab, t[1], bc});
    out.triangles.push_back({ca, bc, t[2]});
    out.triangles.push_back({ab, bc, ca});
  }
  return out;
}

/// The body's collision surface as one mesh, for the hull file or the dense variant.
TriangleMesh surface(const BodyDraft& body, Collision collision) {
  TriangleMesh mesh;
  if (!body.hull.empty()) {
    mesh = convexHull(body.hull);
    if (collision == Collision::Dense) {
      for (int k = 0; k < kDenseJawSubdivisions; ++k) mesh = subdivide(mesh);
    }
    return mesh;
  }
  for (const auto& p : body.primitives) {
    mesh.append(p.tessellate(kDenseSegments), Isometry3d::Identity());
  }
  return mesh;
}

std::size_t weldedVertexCount(const TriangleMesh& mesh) {
  std::set<std::tuple<float, float, float>> unique;
  for (const auto& v : mesh.vertices) unique.emplace(float(v.x()), float(v.y()), float(v.z()));
  return unique.size();
}

}  // namespace

std::size_t writeModel(const ModelDraft& model, Collision collision,
                       const std::filesystem::path& file, const std::filesystem::path& mesh_dir) {
  YAML::Node root;
  const auto relative_mesh_dir = std::filesystem::relative(mesh_dir, file.parent_path());
  std::size_t vertices = 0;
  for (const auto& body : model.bodies) root["bodies"].push_back("BODY " + body.name);
  for (const auto& joint : model.joints) root["joints"].push_back("JOINT " + joint.name);
  root["bodies"].SetStyle(YAML::EmitterStyle::Flow);
  root["joints"].SetStyle(YAML::EmitterStyle::Flow);
  root["high resolution path"] = relative_mesh_dir.string() + "/";
  root["low resolution path"] = relative_mesh_dir.string() + "/";
  root["namespace"] = model.name_space;
  root["ignore inter-collision"] = model.ignore_inter_collision;

  for (const auto& body : model.bodies) {
    YAML::Node b;
    b["name"] = body.name;
    b["mass"] = number(body.mass);
    const auto box = bounds(body);
    const Vector3d com = centreOfMass(body);
    if (body.mass > 0.0) {
      // A box of the body's extent: what Bullet itself would estimate for a compound, given
      // explicitly so both collision variants share the same mass properties.
      const Vector3d e = box.sizes();
      const Vector3d principal =
          Vector3d(e.y() * e.y() + e.z() * e.z(), e.x() * e.x() + e.z() * e.z(),
                   e.x() * e.x() + e.y() * e.y()) *
          (body.mass / 12.0);
      const Vector3d with_armature = principal.cwiseMax(body.armature);
      YAML::Node inertia;
      inertia["ix"] = number(with_armature.x());
      inertia["iy"] = number(with_armature.y());
      inertia["iz"] = number(with_armature.z());
      b["inertia"] = flow(inertia);
      YAML::Node offset;
      offset["position"] = xyz(com);
      b["inertial offset"] = flow(offset);
    }
    b["location"] = pose(body.pose);
    b["collision margin"] = number(body.hull.empty() ? 0.001 : 0.0002);
    YAML::Node damping;
    damping["linear"] = number(0.0);
    damping["angular"] = number(0.0);
    b["damping"] = flow(damping);
    if (body.friction > 0.0) {
      YAML::Node friction;
      friction["static"] = number(body.friction);
      b["friction"] = flow(friction);
    }

    const bool as_mesh = !body.hull.empty() || collision == Collision::Dense;
    if (as_mesh) {
      const TriangleMesh mesh = surface(body, collision);
      const std::string mesh_name =
          body.hull.empty() ? body.name + "_" + model.label + ".obj" : body.hull_mesh;
      mesh.writeObj(mesh_dir / mesh_name, "collision surface of " + model.name_space + body.name +
                                              " (generated by raven_description/tools)");
      vertices += weldedVertexCount(mesh);
      b["mesh"] = mesh_name;
      b["collision mesh type"] = body.hull.empty() ? "CONCAVE_MESH" : "CONVEX_HULL";
    } else {
      int index = 0;
      for (const auto& p : body.primitives)
        b["compound collision shape"].push_back(primitive(p, index++));
      index = 0;
      for (const auto& p : body.primitives) b["compound shape"].push_back(primitive(p, index++));
    }
    root["BODY " + body.name] = b;
  }

  for (const auto& joint : model.joints) {
    YAML::Node j;
    j["name"] = joint.name;
    j["parent"] = "BODY " + joint.parent;
    j["child"] = "BODY " + joint.child;
    j["parent axis"] = xyz(joint.parent_axis);
    j["parent pivot"] = xyz(joint.parent_pivot);
    j["child axis"] = xyz(joint.child_axis);
    j["child pivot"] = xyz(joint.child_pivot);
    j["type"] = joint.prismatic ? "prismatic" : "revolute";
    j["offset"] = number(joint.offset);
    YAML::Node limits;
    limits["low"] = number(joint.low);
    limits["high"] = number(joint.high);
    j["joint limits"] = flow(limits);
    // A stiff position servo: the motor closes the error within its effort limit each step; the
    // twin steps its physics once per robot cycle.
    j["controller output type"] = "POSITION";
    j["max motor impulse"] = number(joint.max_effort * raven::kControlCycle);
    j["max velocity"] = number(joint.max_velocity);
    j["joint erp"] = number(0.8);
    j["joint cfm"] = number(0.0);
    root["JOINT " + joint.name] = j;
  }

  writeYaml(root, model.comment, file);
  return vertices;
}

}  // namespace raven::model
