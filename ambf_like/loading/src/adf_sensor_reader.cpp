#include <cmath>
#include <span>

#include "adf_readers.hpp"

namespace ambf_like::detail {

namespace {

// clang-format off
/// Every sensor key AMBF reads (resistance sensors add theirs; `visible`, `visible size` and
/// `publish frequency` are accepted, not simulated).
constexpr std::string_view kSensorKeys[] = {
    "name", "namespace", "type", "parent", "location", "publish frequency", "range", "visible",
    "visible size", "array", "mesh", "parametric", "friction", "contact area",
    "contact stiffness", "contact damping", "use material", "redundant", "detached"};
constexpr std::string_view kActuatorKeys[] = {
    "name", "namespace", "type", "parent", "location", "publish frequency", "visible",
    "visible size", "max impulse", "tau", "use material", "redundant", "detached"};
// clang-format on

Vec3 unitDirection(const YamlView& node) {
  const Vec3 v = node.asXyz();
  if (!(v.norm() > 1e-12)) node.fail("a ray direction must not be zero");
  return v.normalized();
}

std::vector<SensorRay> readArray(const YamlView& list) {
  std::vector<SensorRay> rays;
  for (const auto& entry : list.elements()) {
    SensorRay ray;
    if (auto offset = entry.find("offset")) ray.origin = offset->asXyz();
    ray.direction = unitDirection(entry["direction"]);
    rays.push_back(ray);
  }
  if (rays.empty()) list.fail("an array sensor needs at least one ray");
  return rays;
}

/// AMBF's parametric fan: resolution x resolution rays about the sensor's +x axis, spanning the
/// horizontal angle (about z) and the vertical angle (about y), starting `start offset` out.
std::vector<SensorRay> readParametric(const YamlView& node, LoadContext& context) {
  node.checkKeys({"resolution", "horizontal angle", "vertical angle", "start offset"},
                 context.keyCheck());
  const int resolution = node["resolution"].asInt();
  // Every ray is cast after every step: 300 x 300 is already 90,000 a step.
  if (resolution < 2 || resolution > 300) {
    node["resolution"].fail("the resolution must be 2 to 300 (resolution x resolution rays)");
  }
  const double horizontal = node["horizontal angle"].asDouble();
  const double vertical = node["vertical angle"].asDouble();
  const double start = node.getDouble("start offset", 0.0);
  std::vector<SensorRay> rays;
  for (int i = 0; i < resolution; ++i) {
    const double h = -horizontal / 2.0 + i * horizontal / (resolution - 1);
    for (int j = 0; j < resolution; ++j) {
      const double v = -vertical / 2.0 + j * vertical / (resolution - 1);
      const Vec3 direction = (quatFromRpy(0.0, v, h) * Vec3::UnitX()).normalized();
      rays.push_back({direction * start, direction});
    }
  }
  return rays;
}

void notSimulated(const YamlView& node, std::initializer_list<const char*> keys,
                  LoadContext& context) {
  for (const char* key : keys) {
    if (auto v = node.find(key)) context.acceptedNotSimulated(v->where(), key);
  }
}

/// What sensors and actuators share: their keys checked, the not-simulated ones noted, and the
/// parts every spec has (name, parent, location, where).
template <typename Spec>
Spec readCommon(const YamlView& node, std::span<const std::string_view> keys,
                const std::string& identifier, LoadContext& context) {
  node.checkKeys(keys, context.keyCheck());
  noteNotSimulated(node, context);
  notSimulated(node, {"visible", "visible size", "publish frequency"}, context);
  Spec spec;
  spec.where = node.where();
  spec.name = node.has("name") ? node["name"].asString() : stripPrefix(identifier);
  spec.parent = stripPrefix(node["parent"].asString());
  if (auto location = node.find("location")) spec.location = location->asPose();
  return spec;
}

}  // namespace

SensorSpec readSensor(const YamlView& node, const std::string& identifier, LoadContext& context) {
  auto sensor = readCommon<SensorSpec>(node, kSensorKeys, identifier, context);
  const auto type = node["type"];
  const std::string kind = type.asKeyword();
  if (kind == "proximity" || kind == "raytracer") {
    sensor.type = SensorType::Proximity;
  } else if (kind == "resistance") {
    sensor.type = SensorType::Resistance;
    notSimulated(node, {"friction", "contact area", "contact stiffness", "contact damping"},
                 context);
  } else {
    type.fail("unknown sensor type '" + type.asString() +
              "' (expected PROXIMITY, RAYTRACER or RESISTANCE)");
  }
  sensor.range = node["range"].asDouble();
  if (!(sensor.range > 0.0)) node["range"].fail("the range must be greater than zero");
  if (auto array = node.find("array")) {
    sensor.rays = readArray(*array);
  } else if (auto parametric = node.find("parametric")) {
    sensor.rays = readParametric(*parametric, context);
  } else if (auto mesh = node.find("mesh")) {
    mesh->fail(
        "a sensor whose rays follow a mesh's contour is not supported; give 'array' or "
        "'parametric'");
  } else {
    node.fail("sensor '" + sensor.name + "' gives no rays: 'array' or 'parametric'");
  }
  return sensor;
}

ActuatorSpec readActuator(const YamlView& node, const std::string& identifier,
                          LoadContext& context) {
  auto actuator = readCommon<ActuatorSpec>(node, kActuatorKeys, identifier, context);
  const auto type = node["type"];
  if (type.asKeyword() != "constraint") {
    type.fail("unknown actuator type '" + type.asString() + "' (expected CONSTRAINT)");
  }
  actuator.max_impulse = node.getDouble("max impulse", actuator.max_impulse);
  if (actuator.max_impulse < 0.0) node["max impulse"].fail("must not be negative");
  actuator.tau = node.getDouble("tau", actuator.tau);
  if (!(actuator.tau > 0.0 && actuator.tau <= 1.0)) node["tau"].fail("must be within (0, 1]");
  return actuator;
}

}  // namespace ambf_like::detail
