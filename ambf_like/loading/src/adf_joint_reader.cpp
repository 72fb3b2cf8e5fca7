#include <map>

#include "adf_readers.hpp"

namespace ambf_like::detail {

namespace {

JointType readType(const YamlView& node) {
  static const std::map<std::string, JointType> kTypes = {
      {"revolute", JointType::Revolute},
      {"hinge", JointType::Revolute},
      {"continuous", JointType::Continuous},
      {"prismatic", JointType::Prismatic},
      {"slider", JointType::Prismatic},
      {"fixed", JointType::Fixed},
      {"p2p", JointType::P2P},
      {"spring", JointType::LinearSpring},
      {"linear spring", JointType::LinearSpring},
      {"torsion spring", JointType::TorsionSpring},
      {"torsional spring", JointType::TorsionSpring},
      {"angular spring", JointType::TorsionSpring},
      {"cone twist", JointType::ConeTwist},
      {"six dof", JointType::SixDof},
      {"six dof spring", JointType::SixDofSpring},
  };
  const auto it = kTypes.find(node.asKeyword());
  if (it == kTypes.end()) {
    node.fail("unknown joint type '" + node.asString() +
              "' (expected revolute, continuous, prismatic, fixed, p2p, linear spring, "
              "torsion spring, cone twist, six dof or six dof spring)");
  }
  return it->second;
}

ControlOutput readOutputType(const YamlView& node) {
  const auto text = node.asKeyword();
  if (text == "force" || text == "effort") return ControlOutput::Effort;
  if (text == "velocity") return ControlOutput::Velocity;
  if (text == "position") return ControlOutput::Position;
  node.fail("unknown controller output type '" + node.asString() +
            "' (expected FORCE, EFFORT, VELOCITY or POSITION)");
}

Vec3 unitVector(const YamlView& node) {
  const Vec3 v = node.asXyz();
  if (v.norm() < 1e-9) node.fail("axis must not be zero");
  return v.normalized();
}

/// Reads {linear {x,y,z}, angular {x,y,z}} into six values.
SixAxis readSixAxis(const YamlView& node) {
  const Vec3 linear = node["linear"].asXyz();
  const Vec3 angular = node["angular"].asXyz();
  return {linear.x(), linear.y(), linear.z(), angular.x(), angular.y(), angular.z()};
}

void readSingleAxisLimits(const YamlView& node, JointSpec& joint, LoadContext& context) {
  node.checkKeys({"low", "high"}, context.keyCheck());
  const bool has_low = node.has("low");
  const bool has_high = node.has("high");
  if (has_low != has_high) {
    context.warn(node.where(), "joint limits need both 'low' and 'high'; limits left disabled");
    return;
  }
  if (!has_low) return;
  JointLimits limits{node["low"].asDouble(), node["high"].asDouble()};
  if (limits.low > limits.high) node.fail("joint limit 'low' is greater than 'high'");
  joint.limits = limits;
}

void readSixDofLimits(const YamlView& node, JointSpec& joint) {
  for (const char* part : {"linear", "angular"}) {
    const auto block = node[part];
    const Vec3 low = block["low"].asXyz();
    const Vec3 high = block["high"].asXyz();
    const int base = std::string(part) == "linear" ? 0 : 3;
    for (int i = 0; i < 3; ++i) {
      if (low[i] > high[i]) block.fail("'low' is greater than 'high'");
      joint.six_dof.low[base + i] = low[i];
      joint.six_dof.high[base + i] = high[i];
    }
  }
}

void readSpringValues(const YamlView& node, JointSpec& joint) {
  if (joint.type == JointType::SixDofSpring) {
    if (auto v = node.find("stiffness")) joint.six_dof.stiffness = readSixAxis(*v);
    if (auto v = node.find("damping")) joint.six_dof.damping = readSixAxis(*v);
    if (auto v = node.find("equilibrium point")) joint.six_dof.equilibrium = readSixAxis(*v);
    return;
  }
  if (auto v = node.find("damping")) {
    joint.damping = v->asDouble();
    if (joint.damping < 0.0) v->fail("damping must not be negative");
  }
  if (auto v = node.find("stiffness")) {
    joint.stiffness = v->asDouble();
    if (*joint.stiffness < 0.0) v->fail("stiffness must not be negative");
  }
  if (auto v = node.find("equilibrium point")) joint.equilibrium_point = v->asDouble();
}

/// Every joint key of ADF 1.0.
// clang-format off
constexpr std::string_view kJointKeys[] = {
    "name", "namespace", "parent", "child", "parent axis", "parent pivot", "child axis",
    "child pivot", "type", "joint limits", "offset", "child offset", "joint offset", "controller",
    "controller output type", "max motor impulse", "max velocity", "damping", "stiffness", "equilibrium point",
    "enable motor", "enable feedback", "joint erp", "joint cfm", "ignore inter-collision",
    "passive", "publish frequency", "origin", "axis", "use material", "redundant", "detached"};
// clang-format on

}  // namespace

JointSpec readJoint(const YamlView& node, const std::string& identifier,
                    const JointDefaults& defaults, LoadContext& context) {
  node.checkKeys(kJointKeys, context.keyCheck());
  noteNotSimulated(node, context);
  JointSpec joint;
  joint.where = node.where();
  joint.name = node.has("name") ? node["name"].asString() : stripPrefix(identifier);
  joint.parent = stripPrefix(node["parent"].asString());
  joint.child = stripPrefix(node["child"].asString());
  if (joint.parent == joint.child) node["child"].fail("a joint cannot connect a body to itself");
  if (auto v = node.find("type")) joint.type = readType(*v);

  if (auto v = node.find("parent axis")) joint.parent_axis = unitVector(*v);
  if (auto v = node.find("child axis")) joint.child_axis = unitVector(*v);
  if (auto v = node.find("parent pivot")) joint.parent_pivot = v->asXyz();
  if (auto v = node.find("child pivot")) joint.child_pivot = v->asXyz();

  if (node.has("offset") && node.has("child offset")) {
    node["child offset"].fail("give either 'offset' or 'child offset' (they are the same value)");
  }
  if (auto v = node.find("offset")) joint.child_offset = v->asDouble();
  if (auto v = node.find("child offset")) joint.child_offset = v->asDouble();
  if (auto v = node.find("joint offset")) joint.joint_offset = v->asDouble();

  if (auto limits = node.find("joint limits")) {
    switch (joint.type) {
      case JointType::ConeTwist:
        joint.cone_twist_limits = limits->asXyz();
        break;
      case JointType::SixDof:
      case JointType::SixDofSpring:
        readSixDofLimits(*limits, joint);
        break;
      case JointType::Continuous:
        if (!limits->keys().empty()) {
          context.warn(limits->where(), "a continuous joint has no limits; ignored");
        }
        break;
      default:
        readSingleAxisLimits(*limits, joint, context);
    }
  }
  readSpringValues(node, joint);

  // AMBF: a `controller` block makes the PID output an effort; without one a velocity-output
  // PID (P 10, I 0, D 1) drives the joint motor. An explicit output type overrides either.
  if (auto controller = node.find("controller")) {
    controller->checkKeys({"P", "I", "D"}, context.keyCheck());
    joint.controller = {(*controller)["P"].asDouble(), controller->getDouble("I", 0.0),
                        (*controller)["D"].asDouble()};
    joint.output = ControlOutput::Effort;
  }
  if (auto v = node.find("controller output type")) joint.output = readOutputType(*v);

  if (auto v = node.find("max motor impulse")) {
    joint.max_motor_impulse = v->asDouble();
    if (joint.max_motor_impulse < 0.0) v->fail("max motor impulse must not be negative");
  }
  if (auto v = node.find("max velocity")) {
    joint.max_velocity = v->asDouble();
    if (*joint.max_velocity <= 0.0) v->fail("max velocity must be positive");
  }
  joint.enable_motor = node.getBool("enable motor", true);
  joint.enable_feedback = node.getBool("enable feedback", false);
  joint.erp = node.getDouble("joint erp", defaults.erp);
  joint.cfm = node.getDouble("joint cfm", defaults.cfm);
  joint.ignore_inter_collision = node.getBool("ignore inter-collision", true);
  joint.passive = node.getBool("passive", false);
  return joint;
}

}  // namespace ambf_like::detail
