#pragma once
// Small helpers that turn Eigen values into the flow-style YAML nodes ADF files use.

#include <yaml-cpp/yaml.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

namespace raven::model {

/// A number with 10 significant digits (yaml-cpp would print every double with 17); rounding
/// noise below 1e-12 (a picometre, a picoradian) is written as 0, so the files do not depend on
/// how the compiler contracts floating point (-march=native fuses multiply-adds).
inline YAML::Node number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.10g", std::abs(value) < 1e-12 ? 0.0 : value);
  return YAML::Node(std::string(text));
}

inline YAML::Node flow(YAML::Node node) {
  node.SetStyle(YAML::EmitterStyle::Flow);
  return node;
}

/// {x, y, z}
inline YAML::Node xyz(const Eigen::Vector3d& v) {
  YAML::Node n;
  n["x"] = number(v.x());
  n["y"] = number(v.y());
  n["z"] = number(v.z());
  return flow(n);
}

/// {position {x, y, z}, orientation {r, p, y}} with R = Rz(y) Ry(p) Rx(r).
inline YAML::Node pose(const Eigen::Isometry3d& t) {
  const Eigen::Vector3d ypr = t.linear().eulerAngles(2, 1, 0);
  YAML::Node n;
  n["position"] = xyz(t.translation());
  YAML::Node o;
  o["r"] = number(ypr.z());
  o["p"] = number(ypr.y());
  o["y"] = number(ypr.x());
  n["orientation"] = flow(o);
  return flow(n);
}

/// Writes `root` to `file` (its folder created) under a comment line, numbers at 12 digits.
inline void writeYaml(const YAML::Node& root, const std::string& comment,
                      const std::filesystem::path& file) {
  YAML::Emitter out;
  out.SetDoublePrecision(12);
  out << YAML::Comment(comment) << root;
  std::filesystem::create_directories(file.parent_path());
  std::ofstream stream(file);
  if (!stream) throw std::runtime_error("cannot write " + file.string());
  stream << out.c_str() << "\n";
}

}  // namespace raven::model
