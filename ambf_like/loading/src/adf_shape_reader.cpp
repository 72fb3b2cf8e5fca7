#include "adf_readers.hpp"

namespace ambf_like::detail {

namespace {

Axis readAxis(const YamlView& geometry) {
  auto node = geometry.find("axis");
  if (!node) return Axis::Z;
  const auto text = node->asKeyword();
  if (text == "x") return Axis::X;
  if (text == "y") return Axis::Y;
  if (text == "z") return Axis::Z;
  node->fail("unknown axis '" + node->asString() + "' (expected X, Y or Z)");
}

double positive(const YamlView& node) {
  const double value = node.asDouble();
  if (value <= 0.0) node.fail("must be greater than zero");
  return value;
}

}  // namespace

PrimitiveShape readPrimitive(const YamlView& shape, const YamlView& geometry,
                             std::optional<Transform> offset) {
  PrimitiveShape out;
  out.offset = std::move(offset);
  const auto type = shape.asKeyword();
  if (type == "box") {
    out.type = PrimitiveType::Box;
    out.box_size = Vec3(positive(geometry["x"]), positive(geometry["y"]), positive(geometry["z"]));
  } else if (type == "sphere") {
    out.type = PrimitiveType::Sphere;
    out.radius = positive(geometry["radius"]);
  } else if (type == "cylinder" || type == "capsule" || type == "cone") {
    out.type = type == "cylinder"  ? PrimitiveType::Cylinder
               : type == "capsule" ? PrimitiveType::Capsule
                                   : PrimitiveType::Cone;
    out.radius = positive(geometry["radius"]);
    out.height = positive(geometry["height"]);
    out.axis = readAxis(geometry);
  } else if (type == "plane") {
    out.type = PrimitiveType::Plane;
    out.plane_normal = geometry["normal"].asXyz();
    if (out.plane_normal.norm() < 1e-9) geometry["normal"].fail("plane normal must not be zero");
    out.plane_normal.normalize();
    out.plane_offset = geometry["offset"].asDouble();
  } else {
    shape.fail("unknown shape '" + shape.asString() +
               "' (expected BOX, SPHERE, CYLINDER, CAPSULE, CONE or PLANE)");
  }
  return out;
}

std::vector<PrimitiveShape> readCompoundShape(const YamlView& list, LoadContext& context) {
  std::vector<PrimitiveShape> shapes;
  for (const auto& entry : list.elements()) {
    entry.checkKeys({"name", "shape", "geometry", "offset"}, context.keyCheck());
    std::optional<Transform> offset;
    if (auto node = entry.find("offset")) offset = node->asPose();
    shapes.push_back(readPrimitive(entry["shape"], entry["geometry"], offset));
  }
  if (shapes.empty()) list.fail("compound shape list is empty");
  return shapes;
}

}  // namespace ambf_like::detail
