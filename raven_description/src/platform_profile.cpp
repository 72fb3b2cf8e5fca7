#include "raven/platform_profile.hpp"

#include <cmath>

#include "common/yaml_view.hpp"

namespace raven {

namespace {

using common::YamlView;

constexpr double kDegree = M_PI / 180.0;

Eigen::Isometry3d readBase(const YamlView& node, std::vector<common::LoadIssue>& warnings) {
  node.checkKeys({"rows", "rz_deg"}, {true, warnings});
  const auto rows = node["rows"].elements();
  if (rows.size() != 3) node["rows"].fail("expected 3 rows of [R | t]");
  Eigen::Isometry3d base = Eigen::Isometry3d::Identity();
  for (int r = 0; r < 3; ++r) {
    const auto values = rows[static_cast<std::size_t>(r)].asDoubleList(4);
    for (int c = 0; c < 3; ++c) base.linear()(r, c) = values[static_cast<std::size_t>(c)];
    base.translation()(r) = values[3];
  }
  const Eigen::Matrix3d rotation = base.linear();
  if (!(rotation.transpose() * rotation).isIdentity(1e-9) || rotation.determinant() < 0.0) {
    node["rows"].fail("the 3x3 part is not a rotation");
  }
  base.rotate(Eigen::AngleAxisd(node["rz_deg"].asDouble() * kDegree, Eigen::Vector3d::UnitZ()));
  return base;
}

ArmConvention readConvention(const YamlView& node, Arm arm,
                             std::vector<common::LoadIssue>& warnings) {
  node.checkKeys({"d4", "tool_length", "alpha_deg", "insertion_theta_deg", "theta_offset_deg",
                  "grasp_scale", "base"},
                 {true, warnings});
  const std::string side(armName(arm));
  ArmConvention c;
  c.d4 = node["d4"].asDouble();
  c.tool_length = node["tool_length"].asDouble();
  const auto alpha = node["alpha_deg"][side].asDoubleList(6);
  for (std::size_t i = 0; i < 6; ++i) c.alpha[i] = alpha[i] * kDegree;
  if (std::abs(std::abs(c.alpha[5]) - M_PI / 2) > 1e-12) {
    node["alpha_deg"][side].fail("row 5 must be +-90 deg (the closed-form inverse assumes it)");
  }
  c.insertion_theta = node["insertion_theta_deg"][side].asDouble() * kDegree;
  const auto offsets = node["theta_offset_deg"][side].asDoubleList(5);
  for (std::size_t i = 0; i < 5; ++i) c.theta_offset[i] = offsets[i] * kDegree;
  c.grasp_scale = node["grasp_scale"][side].asDouble();
  if (c.grasp_scale == 0.0) node["grasp_scale"][side].fail("grasp_scale must not be zero");
  c.base = readBase(node["base"][side], warnings);
  return c;
}

raven::PerArm<ArmConvention> readConventions(const YamlView& node,
                                             std::vector<common::LoadIssue>& warnings) {
  return {readConvention(node, Arm::Left, warnings), readConvention(node, Arm::Right, warnings)};
}

ArmJoints readJoints(const YamlView& node) {
  const auto values = node.asDoubleList(kJointCount);
  return Eigen::Map<const ArmJoints>(values.data());
}

}  // namespace

PlatformProfile loadPlatformProfile(const std::filesystem::path& file) {
  const auto root = YamlView::parseFile(file);
  std::vector<common::LoadIssue> warnings;
  root.checkKeys({"name", "description", "kinematics", "firmware_kinematics", "joints"},
                 {true, warnings});
  PlatformProfile profile;
  profile.name = root["name"].asString();
  if (auto description = root.find("description")) profile.description = description->asString();
  profile.kinematics = readConventions(root["kinematics"], warnings);
  if (auto firmware = root.find("firmware_kinematics")) {
    profile.firmware_kinematics = readConventions(*firmware, warnings);
  }
  const auto joints = root["joints"];
  joints.checkKeys({"home", "robot_home", "limits"}, {true, warnings});
  profile.home = readJoints(joints["home"]);
  if (auto robot_home = joints.find("robot_home")) profile.robot_home = readJoints(*robot_home);
  const auto limits = joints["limits"];
  limits.checkKeys({"low", "high"}, {true, warnings});
  profile.limits.low = readJoints(limits["low"]);
  profile.limits.high = readJoints(limits["high"]);
  for (int i = 0; i < kJointCount; ++i) {
    if (profile.limits.low(i) > profile.limits.high(i)) {
      limits.fail("low > high for joint " + std::string(kJointNames[static_cast<std::size_t>(i)]));
    }
    const std::string name(kJointNames[static_cast<std::size_t>(i)]);
    const auto outside = [&](const ArmJoints& q) {
      return q(i) < profile.limits.low(i) || q(i) > profile.limits.high(i);
    };
    if (outside(profile.home)) joints["home"].fail("home " + name + " is outside the limits");
    if (profile.robot_home && outside(*profile.robot_home)) {
      joints["robot_home"].fail("robot_home " + name + " is outside the limits");
    }
  }
  if (!warnings.empty())
    throw common::LoadError(warnings);  // duplicate keys in a profile are errors
  return profile;
}

std::filesystem::path profileDirectory() {
  return RAVEN_PROFILE_DIR;
}

std::filesystem::path modelDirectory() {
  return RAVEN_MODEL_DIR;
}

PlatformProfile builtinProfile(const std::string& name) {
  return loadPlatformProfile(profileDirectory() / (name + ".yaml"));
}

}  // namespace raven
