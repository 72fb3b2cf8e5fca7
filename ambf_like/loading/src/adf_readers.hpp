#pragma once
// Readers turning ADF YAML nodes into the plain spec structs (one reader per kind of node).

#include <filesystem>
#include <optional>
#include <vector>

#include "ambf_like/scene_spec.hpp"
#include "common/yaml_view.hpp"
#include "load_context.hpp"

namespace ambf_like::detail {

using common::YamlView;

/// The directories a model's relative mesh names are resolved against.
struct MeshDirectories {
  std::filesystem::path high_res;  ///< visual meshes
  std::filesystem::path low_res;   ///< collision and soft-body meshes (falls back to high_res)
};

/// Model-wide defaults a joint inherits.
struct JointDefaults {
  double erp = 0.1;
  double cfm = 0.1;
};

/// A primitive from `shape`/`collision shape` + geometry (+ offset, empty for AMBF's legacy rule).
PrimitiveShape readPrimitive(const YamlView& shape, const YamlView& geometry,
                             std::optional<Transform> offset);
/// A `compound (collision) shape` list.
std::vector<PrimitiveShape> readCompoundShape(const YamlView& list, LoadContext& context);

BodySpec readBody(const YamlView& node, const std::string& identifier, const MeshDirectories& dirs,
                  LoadContext& context);
JointSpec readJoint(const YamlView& node, const std::string& identifier,
                    const JointDefaults& defaults, LoadContext& context);
SoftBodySpec readSoftBody(const YamlView& node, const std::string& identifier,
                          const MeshDirectories& dirs, LoadContext& context);

/// A `sensors` entry (PROXIMITY / RAYTRACER / RESISTANCE with an `array` or `parametric` rays).
SensorSpec readSensor(const YamlView& node, const std::string& identifier, LoadContext& context);
/// An `actuators` entry (CONSTRAINT).
ActuatorSpec readActuator(const YamlView& node, const std::string& identifier,
                          LoadContext& context);

/// A whole multibody (model) file.
ModelSpec readAdfModel(const std::filesystem::path& file, LoadContext& context);

/// The physics settings of a world file; `environment` receives its environment model, if any.
WorldSpec readWorld(const std::filesystem::path& file, LoadContext& context,
                    std::optional<std::filesystem::path>& environment);

/// The model's mesh directories, overridden by a body's own resolution-path keys.
MeshDirectories meshDirectoriesOf(const YamlView& node, const MeshDirectories& model_dirs);

/// Finds `name` in the first directory holding it; reports every place tried when none does.
std::optional<std::filesystem::path> findMesh(const std::string& name,
                                              const std::vector<std::filesystem::path>& dirs,
                                              std::string& tried);

/// Strips an ADF identifier prefix such as "BODY " or "JOINT ".
std::string stripPrefix(const std::string& identifier);

/// Keys AMBF's files carry that this simulator accepts without simulating them.
inline constexpr std::string_view kNotSimulatedKeys[] = {"use material", "redundant", "detached"};
/// Notes each not-simulated key `node` holds ("accepted, not simulated", once per load).
void noteNotSimulated(const YamlView& node, LoadContext& context);

}  // namespace ambf_like::detail
