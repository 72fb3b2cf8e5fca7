// raven_fit_visuals: places AMBF's Raven-II meshes on our Raven-II's links and writes the
// offsets to raven_description/models/raven2/ambf_visuals.yaml (read by the viewer).
//
// Both models are chains of joint axes. A link with an axis in and a non-parallel axis out
// (link1, link2, the shaft, the wrist) has one frame built from those two lines in each model;
// the mesh goes where that frame says, the axis directions' signs picked so that the mesh's
// centroid lands nearest the centre of our link's drawn shapes (not its centre of mass: the
// robot's own puts link 1's on the far side of its axis). The carriage (in and out axes are one
// line) takes its turn from link 2 (it only slides) and its place on the axis from the shaft; the
// jaws hang off the wrist through AMBF's own wrist-to-grasper joints, turned about their axis to
// point where our jaws point. So a grasper mesh's pivot lands where AMBF's geometry puts it, and
// how far that is from our kinematics' tool point is a measured check, not a fit.

#include <spdlog/spdlog.h>

#include <CLI/CLI.hpp>
#include <array>
#include <cmath>
#include <fstream>
#include <map>

#include "ambf_like/mesh.hpp"
#include "ambf_like/scene_loader.hpp"

namespace {

using ambf_like::Transform;
using ambf_like::Vec3;

/// A joint axis as a line in a body's frame.
struct Line {
  Vec3 point, direction;
};

/// One model's bodies and joints by plain name.
struct Chain {
  std::map<std::string, ambf_like::BodySpec> bodies;
  std::vector<ambf_like::JointSpec> joints;
  ambf_like::MeshLibrary meshes;

  static Chain load(const std::filesystem::path& file) {
    ambf_like::LoadOptions lenient;  // AMBF's base_link meshes are missing upstream
    const auto scene = ambf_like::loadModelFiles({file}, std::nullopt, lenient);
    Chain c;
    for (const auto& model : scene.spec.models) {
      for (const auto& body : model.bodies) c.bodies[body.name] = body;
      c.joints.insert(c.joints.end(), model.joints.begin(), model.joints.end());
    }
    return c;
  }
  /// The axis of the joint that moves `body`, in its frame.
  Line in(const std::string& body) const {
    for (const auto& j : joints) {
      if (j.child == body) return {j.child_pivot, j.child_axis.normalized()};
    }
    throw std::runtime_error("no joint moves " + body);
  }
  /// The axes of the joints `body` carries, in its frame.
  std::vector<Line> out(const std::string& body) const {
    std::vector<Line> lines;
    for (const auto& j : joints) {
      if (j.parent == body) lines.push_back({j.parent_pivot, j.parent_axis.normalized()});
    }
    if (lines.empty()) throw std::runtime_error(body + " carries no joint");
    return lines;
  }
  /// `child`'s frame in `parent`'s, as the file lays them out.
  Transform relative(const std::string& parent, const std::string& child) const {
    return bodies.at(parent).location.inverse() * bodies.at(child).location;
  }
  std::vector<Vec3> vertices(const std::string& body) {
    const auto& spec = bodies.at(body);
    std::vector<Vec3> out;
    for (const Vec3& v : meshes.load(spec.visual_mesh, spec.where)->vertices) {
      out.push_back(v * spec.scale);
    }
    return out;
  }
};

/// The frame two non-parallel lines span: origin on `in` nearest `out`, x along `in`, z along
/// in x out.
Transform frameOf(const Line& in, const Line& out) {
  const Vec3 z = in.direction.cross(out.direction);
  if (z.norm() < 1e-6) throw std::runtime_error("parallel axes span no frame");
  // The point of `in` nearest `out`: (p + t d - q) is orthogonal to e x (d x e).
  const Vec3 n = out.direction.cross(z);
  const double t = (out.point - in.point).dot(n) / in.direction.dot(n);
  Transform f = Transform::Identity();
  f.linear().col(0) = in.direction;
  f.linear().col(2) = z.normalized();
  f.linear().col(1) = f.linear().col(2).cross(in.direction);
  f.translation() = in.point + t * in.direction;
  return f;
}

Vec3 centroid(const std::vector<Vec3>& points) {
  Vec3 c = Vec3::Zero();
  for (const Vec3& p : points) c += p;
  return c / static_cast<double>(points.size());
}

/// Where a body's collision primitives sit on average (body frame); its centre of mass without.
Vec3 drawnCentre(const ambf_like::BodySpec& body) {
  Vec3 sum = Vec3::Zero();
  int placed = 0;
  for (const auto& p : body.collision.primitives) {
    if (p.offset) sum += p.offset->translation(), ++placed;
  }
  if (placed > 0) return sum / placed;
  return body.inertial_offset ? Vec3(body.inertial_offset->translation()) : Vec3::Zero();
}

/// The offset of AMBF body `theirs` in our body `ours` from their in and out axes. Where AMBF's
/// body carries several joints (the wrist: two jaws), the one whose angle to the in axis is
/// ours counts (AMBF's right grasper1 axis is 11 degrees off its grasper2's).
Transform fitByAxes(Chain& our, const std::string& ours, Chain& ambf, const std::string& theirs) {
  const Line a_in = ambf.in(theirs);
  const Vec3 mesh_centre = centroid(ambf.vertices(theirs));
  const auto& spec = our.bodies.at(ours);
  const Vec3 our_centre = drawnCentre(spec);
  Transform best = Transform::Identity();
  double best_gap = INFINITY;
  for (const Line& a_out : ambf.out(theirs)) {
    const Transform a = frameOf(a_in, a_out);
    const double angle = a_in.direction.dot(a_out.direction);
    for (double s_in : {1.0, -1.0}) {
      for (double s_out : {1.0, -1.0}) {
        Line o_in = our.in(ours), o_out = our.out(ours).front();
        o_in.direction *= s_in;
        o_out.direction *= s_out;
        if (std::abs(o_in.direction.dot(o_out.direction) - angle) > 0.02) continue;
        const Transform offset = frameOf(o_in, o_out) * a.inverse();
        const double gap = (offset * mesh_centre - our_centre).norm();
        if (gap < best_gap) best_gap = gap, best = offset;
      }
    }
  }
  if (!std::isfinite(best_gap)) throw std::runtime_error(ours + ": the axes' angles differ");
  return best;
}

/// The point farthest from `line`, as a direction across it from the line.
Vec3 across(const Line& line, const std::vector<Vec3>& points) {
  Vec3 far = Vec3::Zero();
  for (const Vec3& p : points) {
    Vec3 r = p - line.point;
    r -= r.dot(line.direction) * line.direction;
    if (r.norm() > far.norm()) far = r;
  }
  return far.normalized();
}

struct Fitted {
  std::string body, mesh;
  Transform offset;
};

/// Our bodies and AMBF's (without its _L / _R), in the order the skin file lists them.
constexpr std::array<std::pair<const char*, const char*>, 7> kBodies{{{"link1", "link1"},
                                                                      {"link2", "link2"},
                                                                      {"carriage", "link3"},
                                                                      {"shaft", "instrument_shaft"},
                                                                      {"wrist_link", "wrist"},
                                                                      {"jaw1_link", "grasper1"},
                                                                      {"jaw2_link", "grasper2"}}};

std::vector<Fitted> fitArm(Chain& our, Chain& ambf, const std::string& side) {
  const std::string s = side == "left" ? "_L" : "_R";
  std::map<std::string, std::string> theirs;
  for (const auto& [ours, name] : kBodies) theirs[ours] = name + s;
  std::map<std::string, Transform> at;
  for (const char* ours : {"link1", "link2", "shaft", "wrist_link"}) {
    at[ours] = fitByAxes(our, ours, ambf, theirs[ours]);
  }
  // The carriage slides on link 2: link 2's turn, the shaft's place on the axis.
  Transform carriage = our.relative("carriage", "link2") * at["link2"] *
                       ambf.relative(theirs["link2"], theirs["carriage"]);
  carriage.translation() = (our.relative("carriage", "shaft") * at["shaft"] *
                            ambf.relative(theirs["carriage"], theirs["shaft"]).inverse())
                               .translation();
  at["carriage"] = carriage;
  // The jaws hang off the wrist through AMBF's joints, turned to point along our jaws.
  for (const char* ours : {"jaw1_link", "jaw2_link"}) {
    const Transform through = our.relative(ours, "wrist_link") * at["wrist_link"] *
                              ambf.relative(theirs["wrist_link"], theirs[ours]);
    const Line axis = ambf.in(theirs[ours]);
    const Vec3 their_tip = across(axis, ambf.vertices(theirs[ours]));
    const Vec3 our_tip = through.linear().transpose() * across(our.in(ours), our.vertices(ours));
    const double turn =
        std::atan2(their_tip.cross(our_tip).dot(axis.direction), their_tip.dot(our_tip));
    Transform spin = Transform::Identity();
    spin.linear() = Eigen::AngleAxisd(turn, axis.direction).toRotationMatrix();
    at[ours] =
        through * Eigen::Translation3d(axis.point) * spin * Eigen::Translation3d(-axis.point);
  }
  std::vector<Fitted> out;
  for (const auto& [ours, name] : kBodies) {
    out.push_back({"/raven2/" + side + "/" + ours, theirs[ours] + ".STL", at[ours]});
  }
  return out;
}

/// Where AMBF's Raven meshes are, from raven_description/models/raven2: ../shared beside the
/// repository, where the project keeps AMBF's files (the same wherever the fit ran).
constexpr const char* kMeshPath =
    "../../../../shared/data/ambf/ambf_models/meshes/blender_afmb/raven_2/low_res";

std::string yamlPose(const Transform& t) {
  const Vec3 ypr = t.rotation().eulerAngles(2, 1, 0);
  const Vec3& p = t.translation();
  return fmt::format(
      "{{position: {{x: {:.9g}, y: {:.9g}, z: {:.9g}}}, orientation: {{r: {:.9g}, p: {:.9g}, "
      "y: {:.9g}}}}}",
      p.x(), p.y(), p.z(), ypr.z(), ypr.y(), ypr.x());
}

}  // namespace

int main(int argc, char** argv) {
  std::string ambf_model =
      "../shared/data/ambf/ambf_models/descriptions/multi-bodies/robots/blender-raven2.yaml";
  std::string models = "raven_description/models/raven2";
  std::string out_name;
  CLI::App app{"raven_fit_visuals: AMBF's Raven-II meshes placed on our Raven-II's links"};
  app.add_option("--ambf-model", ambf_model, "AMBF's blender-raven2.yaml")
      ->check(CLI::ExistingFile);
  app.add_option("--models", models,
                 "our raven2 model folder (reads raven2_*.yaml, writes "
                 "ambf_visuals.yaml)")
      ->check(CLI::ExistingDirectory);
  app.add_option("--out", out_name, "write here instead of MODELS/ambf_visuals.yaml");
  CLI11_PARSE(app, argc, argv);
  try {
    Chain ambf = Chain::load(ambf_model);
    const auto out_file = out_name.empty() ? std::filesystem::path(models) / "ambf_visuals.yaml"
                                           : std::filesystem::path(out_name);
    std::ofstream out(out_file);
    out << "# AMBF's Raven-II meshes (blender-raven2.yaml's low-resolution STL files) on our "
           "links: each\n"
           "# body's mesh file and its frame in our body frame. Written by raven_fit_visuals "
           "(twin/tools);\n"
           "# do not edit by hand. The meshes are AMBF's and are not copied here: the viewer "
           "looks for them\n"
           "# in $RAVEN_AMBF_MESHES, else in `mesh path` (relative to this file), and draws the "
           "collision\n"
           "# shapes when they are absent.\n"
        << "mesh path: " << kMeshPath << "\nbodies:\n";
    for (const std::string side : {"left", "right"}) {
      Chain our = Chain::load(std::filesystem::path(models) / ("raven2_" + side + ".yaml"));
      for (const Fitted& f : fitArm(our, ambf, side)) {
        out << "  " << f.body << ": {mesh: " << f.mesh << ", offset: " << yamlPose(f.offset)
            << "}\n";
        spdlog::info("{}: {} at {:.4f} m from the body origin", f.body, f.mesh,
                     f.offset.translation().norm());
      }
    }
    if (!out) throw std::runtime_error("cannot write " + out_file.string());
    spdlog::info("wrote {}", out_file.string());
    return 0;
  } catch (const std::exception& e) {
    spdlog::error("{}", e.what());
    return 1;
  }
}
