#include <set>
#include <unordered_map>

#include "adf_readers.hpp"
#include "common/file_problem.hpp"

namespace ambf_like::detail {

namespace {

SoftBodySleep readSoftBodySleep(const YamlView& node, LoadContext& context) {
  node.checkKeys({"enabled", "distance", "time", "wake distance"}, context.keyCheck());
  SoftBodySleep sleep;
  sleep.enabled = node.getBool("enabled", sleep.enabled);
  sleep.distance = node.getDouble("distance", sleep.distance);
  sleep.time = node.getDouble("time", sleep.time);
  sleep.wake_distance = node.getDouble("wake distance", sleep.wake_distance);
  if (sleep.distance <= 0.0) node["distance"].fail("the resting distance must be positive");
  if (sleep.time <= 0.0) node["time"].fail("the resting time must be positive");
  if (sleep.wake_distance < 0.0)
    node["wake distance"].fail("the wake distance must not be negative");
  return sleep;
}

RigidBodySleep readRigidBodySleep(const YamlView& node, LoadContext& context) {
  node.checkKeys({"enabled", "linear speed", "angular speed"}, context.keyCheck());
  RigidBodySleep sleep;
  sleep.enabled = node.getBool("enabled", sleep.enabled);
  sleep.linear_speed = node.getDouble("linear speed", sleep.linear_speed);
  sleep.angular_speed = node.getDouble("angular speed", sleep.angular_speed);
  if (!(sleep.linear_speed >= 0.0)) node["linear speed"].fail("the speed must not be negative");
  if (!(sleep.angular_speed >= 0.0)) node["angular speed"].fail("the speed must not be negative");
  return sleep;
}

}  // namespace

namespace {

/// The definitions of the identifiers listed under `section` (e.g. `bodies: [BODY a, BODY b]`),
/// looked up in the file's top-level mapping `definitions` (YamlView::children).
std::vector<std::pair<std::string, YamlView>> listedDefinitions(
    const YamlView& root, const std::unordered_map<std::string, YamlView>& definitions,
    const char* section) {
  std::vector<std::pair<std::string, YamlView>> out;
  auto list = root.find(section);
  if (!list || list->isNull()) return out;
  for (const auto& entry : list->elements()) {
    const auto identifier = entry.asString();
    const auto found = definitions.find(identifier);
    const std::optional<YamlView> definition =
        found == definitions.end() ? std::nullopt : std::optional<YamlView>(found->second);
    if (!definition) {
      entry.fail("'" + identifier + "' is listed in '" + section +
                 "' but not defined in this file");
    }
    if (!definition->isMap()) definition->fail("expected a mapping for '" + identifier + "'");
    out.emplace_back(identifier, *definition);
  }
  return out;
}

void warnUnsupported(const YamlView& root, LoadContext& context) {
  for (const char* section : {"ghost objects", "cameras", "lights", "vehicles", "volumes"}) {
    auto list = root.find(section);
    if (list && list->isSequence() && !list->elements().empty()) {
      context.warn(list->where(), std::string(section) + " are not simulated; ignored");
    }
  }
}

void checkJointBodies(const ModelSpec& model, const std::vector<YamlView>& joint_nodes) {
  std::set<std::string> rigid;
  for (const auto& body : model.bodies) rigid.insert(body.name);
  for (std::size_t i = 0; i < model.joints.size(); ++i) {
    const auto& joint = model.joints[i];
    for (const char* side : {"parent", "child"}) {
      const auto& name = std::string(side) == "parent" ? joint.parent : joint.child;
      if (!rigid.count(name)) {
        joint_nodes[i][side].fail("joint '" + joint.name + "': " + side + " body '" + name +
                                  "' is not a rigid body of this model");
      }
    }
  }
}

}  // namespace

void noteNotSimulated(const YamlView& node, LoadContext& context) {
  for (const auto key : kNotSimulatedKeys) {
    if (auto v = node.find(key)) context.acceptedNotSimulated(v->where(), std::string(key));
  }
}

std::string stripPrefix(const std::string& identifier) {
  for (const char* prefix :
       {"BODY ", "JOINT ", "SOFTBODY ", "SOFT BODY ", "SENSOR ", "ACTUATOR "}) {
    const std::string p(prefix);
    if (identifier.rfind(p, 0) == 0) return identifier.substr(p.size());
  }
  return identifier;
}

MeshDirectories meshDirectoriesOf(const YamlView& node, const MeshDirectories& model_dirs) {
  MeshDirectories dirs = model_dirs;
  const auto model_dir = node.file().parent_path();
  if (auto p = node.find("high resolution path")) dirs.high_res = model_dir / p->asString();
  if (auto p = node.find("low resolution path")) dirs.low_res = model_dir / p->asString();
  return dirs;
}

std::optional<std::filesystem::path> findMesh(const std::string& name,
                                              const std::vector<std::filesystem::path>& dirs,
                                              std::string& tried) {
  tried.clear();
  for (const auto& dir : dirs) {
    const auto candidate = (dir / name).lexically_normal();
    if (common::isReadableFile(candidate)) return candidate;
    if (tried.find(candidate.string()) != std::string::npos) continue;
    if (!tried.empty()) tried += ", ";
    tried += candidate.string();
  }
  return std::nullopt;
}

ModelSpec readAdfModel(const std::filesystem::path& file, LoadContext& context) {
  const auto root = YamlView::parseFile(file);
  root.checkSectionKeys({"adf version",
                         "high resolution path",
                         "low resolution path",
                         "namespace",
                         "bodies",
                         "soft bodies",
                         "ghost objects",
                         "joints",
                         "sensors",
                         "actuators",
                         "cameras",
                         "lights",
                         "vehicles",
                         "volumes",
                         "ignore inter-collision",
                         "gravity",
                         "shaders",
                         "plugins",
                         "joint erp",
                         "joint cfm",
                         "parent",
                         "use material",
                         "redundant",
                         "detached"},
                        context.keyCheck());
  noteNotSimulated(root, context);
  if (auto parent = root.find("parent")) context.acceptedNotSimulated(parent->where(), "parent");
  if (auto version = root.find("adf version"); version && version->asString() != "1.0") {
    version->fail("unsupported ADF version '" + version->asString() + "' (only 1.0 exists)");
  }
  ModelSpec model;
  model.file = file;
  model.name_space = root.has("namespace") ? root["namespace"].asString() : "/ambf/env/";
  model.ignore_inter_collision = root.getBool("ignore inter-collision", false);
  if (auto gravity = root.find("gravity")) model.gravity = gravity->asXyz();

  const auto dir = file.parent_path();
  MeshDirectories dirs;
  dirs.high_res =
      root.has("high resolution path") ? dir / root["high resolution path"].asString() : dir;
  dirs.low_res = root.has("low resolution path") ? dir / root["low resolution path"].asString()
                                                 : dirs.high_res;
  const JointDefaults joint_defaults{root.getDouble("joint erp", 0.1),
                                     root.getDouble("joint cfm", 0.1)};

  const auto definitions = root.children();
  std::set<std::string> names;
  auto claimName = [&names](const std::string& name, const YamlView& node) {
    if (!names.insert(name).second) node.fail("another body of this model is named '" + name + "'");
  };
  for (const auto& [identifier, node] : listedDefinitions(root, definitions, "bodies")) {
    model.bodies.push_back(readBody(node, identifier, dirs, context));
    claimName(model.bodies.back().name, node);
  }
  for (const auto& [identifier, node] : listedDefinitions(root, definitions, "soft bodies")) {
    model.soft_bodies.push_back(readSoftBody(node, identifier, dirs, context));
    claimName(model.soft_bodies.back().name, node);
  }
  std::vector<YamlView> joint_nodes;
  for (const auto& [identifier, node] : listedDefinitions(root, definitions, "joints")) {
    model.joints.push_back(readJoint(node, identifier, joint_defaults, context));
    joint_nodes.push_back(node);
  }
  checkJointBodies(model, joint_nodes);
  std::set<std::string> rigid;
  for (const auto& body : model.bodies) rigid.insert(body.name);
  auto parentKnown = [&](const std::string& parent, const std::string& what, const YamlView& node) {
    // A namespace-qualified parent ("/raven2/left/jaw1_link") may be a body of another model,
    // as AMBF finds it: the scene loader resolves it against the models loaded before.
    if (rigid.count(parent) || parent.starts_with('/')) return true;
    context.tolerate(node["parent"].where(), what + ": parent body '" + parent +
                                                 "' is not a rigid body of this model; ignored");
    return false;
  };
  for (const auto& [identifier, node] : listedDefinitions(root, definitions, "sensors")) {
    auto sensor = readSensor(node, identifier, context);
    if (parentKnown(sensor.parent, "sensor '" + sensor.name + "'", node)) {
      model.sensors.push_back(std::move(sensor));
    }
  }
  for (const auto& [identifier, node] : listedDefinitions(root, definitions, "actuators")) {
    auto actuator = readActuator(node, identifier, context);
    if (parentKnown(actuator.parent, "actuator '" + actuator.name + "'", node)) {
      model.actuators.push_back(std::move(actuator));
    }
  }
  warnUnsupported(root, context);
  return model;
}

WorldSpec readWorld(const std::filesystem::path& file, LoadContext& context,
                    std::optional<std::filesystem::path>& environment) {
  const auto root = YamlView::parseFile(file);
  // Lights, cameras, skybox, enclosure and shaders are accepted for compatibility; the
  // physics does not use them.
  root.checkSectionKeys(
      {"adf version", "namespace", "enclosure", "enclosure size", "lights", "cameras",
       "environment", "skybox", "max iterations", "gravity", "shaders", "plugins", "ambf_like"},
      context.keyCheck());
  WorldSpec world;
  world.file = file;
  if (auto ns = root.find("namespace")) world.name_space = ns->asString();
  if (auto gravity = root.find("gravity")) world.gravity = gravity->asXyz();
  if (auto iterations = root.find("max iterations")) {
    world.max_iterations = iterations->asInt();
    if (world.max_iterations < 1 || world.max_iterations > 1000) {
      iterations->fail("max iterations must be 1 to 1000");
    }
  }
  if (auto own = root.find("ambf_like")) {
    own->checkKeys({"solver iterations", "soft body sdf voxel size", "soft body sleep",
                    "rigid body sleep", "articulation"},
                   context.keyCheck());
    if (auto v = own->find("solver iterations")) {
      world.solver_iterations = v->asInt();
      if (*world.solver_iterations < 1 || *world.solver_iterations > 1000) {
        v->fail("solver iterations must be 1 to 1000");
      }
    }
    if (auto v = own->find("soft body sdf voxel size")) {
      world.sdf_voxel_size = v->asDouble();
      if (*world.sdf_voxel_size <= 0.0) v->fail("the voxel size must be positive");
    }
    if (auto v = own->find("soft body sleep"))
      world.soft_body_sleep = readSoftBodySleep(*v, context);
    if (auto v = own->find("rigid body sleep"))
      world.rigid_body_sleep = readRigidBodySleep(*v, context);
    if (auto v = own->find("articulation")) {
      const std::string mode = v->asString();
      if (mode == "automatic") {
        world.articulation = Articulation::Automatic;
      } else if (mode == "maximal") {
        world.articulation = Articulation::Maximal;
      } else if (mode == "reduced") {
        world.articulation = Articulation::Reduced;
      } else {
        v->fail("articulation must be 'automatic', 'maximal' or 'reduced', not '" + mode + "'");
      }
    }
  }
  environment.reset();
  if (auto env = root.find("environment")) {
    const auto path = (file.parent_path() / env->asString()).lexically_normal();
    if (common::isReadableFile(path)) {
      environment = path;
    } else {
      context.tolerate(env->where(),
                       "environment file " + path.string() + " not found; continuing without it");
    }
  }
  return world;
}

}  // namespace ambf_like::detail
