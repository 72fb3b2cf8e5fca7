#include "ambf_like/scene_loader.hpp"

#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

#include "adf_readers.hpp"
#include "common/file_problem.hpp"
#include "common/lower_case.hpp"
#include "urdf_reader.hpp"

namespace ambf_like {

namespace {

using common::YamlView;
using detail::LoadContext;

ModelSpec readModel(const std::filesystem::path& file, LoadContext& context) {
  if (common::lowerCase(file.extension().string()) == ".urdf")
    return detail::readUrdfModel(file, context);
  return detail::readAdfModel(file, context);
}

/// A sensor's or actuator's qualified parent must be a rigid body of a model before it; those
/// whose parent is not are dropped, as AMBF skips them (a warning; an error under --strict).
template <typename Spec>
void keepResolvable(std::vector<Spec>& specs, const std::set<std::string>& known,
                    LoadContext& context, const char* what) {
  std::erase_if(specs, [&](const Spec& spec) {
    if (!spec.parent.starts_with('/') || known.count(spec.parent) != 0) return false;
    SourceRef at = spec.where;
    at.key_path += "/parent";
    context.tolerate(at, std::string(what) + " '" + spec.name + "': parent body '" + spec.parent +
                             "' is not a rigid body of a model loaded before it; skipped");
    return true;
  });
}

/// Checks the qualified parents of models[first...] against every model before each.
void resolveQualifiedParents(std::vector<ModelSpec>& models, std::size_t first,
                             LoadContext& context) {
  std::set<std::string> known;
  for (std::size_t m = 0; m < models.size(); ++m) {
    if (m >= first) {
      keepResolvable(models[m].sensors, known, context, "sensor");
      keepResolvable(models[m].actuators, known, context, "actuator");
    }
    for (const auto& body : models[m].bodies) known.insert(models[m].name_space + body.name);
  }
}

/// A name with the smallest count appended (1, 2, ...) that no name in `taken` has: AMBF's
/// remapping of a name another model already uses.
std::string nonCollidingName(const std::string& name_space, const std::string& name,
                             const std::set<std::string>& taken) {
  for (int count = 1;; ++count) {
    const std::string candidate = name + std::to_string(count);
    if (taken.count(name_space + candidate) == 0) return candidate;
  }
}

/// Bodies, soft bodies and joints of models[first...] whose qualified names a model before
/// them has are renamed as AMBF renames them (a count appended: loading a model twice gives
/// `box` and `box1`), with a warning; references within the model follow.
void remapDuplicateNames(std::vector<ModelSpec>& models, std::size_t first, LoadContext& context) {
  std::set<std::string> bodies, soft_bodies, joints;
  auto remap = [&](ModelSpec& model, auto& specs, std::set<std::string>& taken, const char* what,
                   std::map<std::string, std::string>* renamed) {
    for (auto& spec : specs) {
      if (taken.count(model.name_space + spec.name) != 0) {
        const std::string name = nonCollidingName(model.name_space, spec.name, taken);
        context.warn(spec.where, std::string(what) + " '" + model.name_space + spec.name +
                                     "' has the name of one loaded before it: renamed '" + name +
                                     "', as AMBF renames it");
        if (renamed) (*renamed)[spec.name] = name;
        spec.name = name;
      }
      taken.insert(model.name_space + spec.name);
    }
  };
  for (std::size_t m = 0; m < models.size(); ++m) {
    ModelSpec& model = models[m];
    if (m < first) {
      for (const auto& b : model.bodies) bodies.insert(model.name_space + b.name);
      for (const auto& b : model.soft_bodies) soft_bodies.insert(model.name_space + b.name);
      for (const auto& j : model.joints) joints.insert(model.name_space + j.name);
      continue;
    }
    std::map<std::string, std::string> renamed;
    remap(model, model.bodies, bodies, "body", &renamed);
    remap(model, model.soft_bodies, soft_bodies, "soft body", nullptr);
    remap(model, model.joints, joints, "joint", nullptr);
    auto follow = [&](std::string& reference) {
      if (auto it = renamed.find(reference); it != renamed.end()) reference = it->second;
    };
    for (auto& joint : model.joints) {
      follow(joint.parent);
      follow(joint.child);
    }
    for (auto& sensor : model.sensors) follow(sensor.parent);
    for (auto& actuator : model.actuators) follow(actuator.parent);
  }
}

LoadedScene assemble(const std::vector<std::filesystem::path>& model_files,
                     const std::optional<std::filesystem::path>& world_file, LoadContext& context) {
  LoadedScene scene;
  std::optional<std::filesystem::path> environment;
  if (world_file) scene.spec.world = detail::readWorld(*world_file, context, environment);
  if (environment) scene.spec.models.push_back(readModel(*environment, context));
  for (const auto& file : model_files) scene.spec.models.push_back(readModel(file, context));
  remapDuplicateNames(scene.spec.models, 0, context);
  resolveQualifiedParents(scene.spec.models, 0, context);
  context.throwIfDeferred();
  if (scene.spec.models.empty()) {
    throw LoadError(SourceRef{world_file.value_or(""), 0, ""}, "no model to load");
  }
  scene.warnings = context.takeWarnings();
  return scene;
}

}  // namespace

std::vector<int> parseLaunchIndices(const std::string& text) {
  std::vector<int> indices;
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ',')) {
    std::size_t used = 0;
    int value = -1;
    try {
      value = std::stoi(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != item.size() || value < 0) {
      throw std::invalid_argument("launch index '" + item + "' in '" + text +
                                  "' is not a non-negative integer");
    }
    indices.push_back(value);
  }
  if (indices.empty()) throw std::invalid_argument("no launch index given");
  return indices;
}

LoadedScene loadLaunchFile(const std::filesystem::path& launch_file,
                           const LaunchSelection& selection, const LoadOptions& options) {
  LoadContext context(options);
  const auto root = YamlView::parseFile(launch_file);
  // Colour and input-device files are read by AMBF's graphics and device layers, not its physics.
  root.checkKeys({"adf version", "world config", "color config", "input devices config",
                  "multibody configs", "plugins"},
                 context.keyCheck());
  const auto dir = launch_file.parent_path();
  std::vector<std::filesystem::path> files;
  std::vector<YamlView> entries;
  if (auto list = root.find("multibody configs")) entries = list->elements();

  std::vector<int> indices = selection.indices;
  if (indices.empty()) {
    for (int i = 0; i < static_cast<int>(entries.size()); ++i) indices.push_back(i);
  }
  for (int index : indices) {
    if (index < 0 || index >= static_cast<int>(entries.size())) {
      throw LoadError(
          SourceRef{launch_file, 0, "multibody configs"},
          "launch index " + std::to_string(index) + " does not exist (the file lists " +
              std::to_string(entries.size()) + " multibody configs" +
              (entries.empty() ? "" : ", indices 0.." + std::to_string(entries.size() - 1)) + ")");
    }
    const auto& entry = entries[static_cast<std::size_t>(index)];
    const auto path = (dir / entry.asString()).lexically_normal();
    if (const auto problem = common::fileProblem(path); !problem.empty()) {
      const std::string missing =
          "multibody config " + std::to_string(index) + " (" + path.string() + "): " + problem;
      if (!selection.indices.empty()) entry.fail(missing);  // asked for by index: an error
      context.tolerate(entry.where(), missing + "; skipped");
      continue;
    }
    files.push_back(path);
  }
  for (const auto& extra : selection.extra_files) files.push_back(extra);

  std::optional<std::filesystem::path> world_file;
  if (auto world = root.find("world config")) {
    world_file = (dir / world->asString()).lexically_normal();
    if (const auto problem = common::fileProblem(*world_file); !problem.empty()) {
      world->fail("world config " + world_file->string() + ": " + problem);
    }
  }
  return assemble(files, world_file, context);
}

LoadedScene loadModelFiles(const std::vector<std::filesystem::path>& model_files,
                           const std::optional<std::filesystem::path>& world_file,
                           const LoadOptions& options) {
  LoadContext context(options);
  return assemble(model_files, world_file, context);
}

std::vector<LoadIssue> appendModelFiles(SceneSpec& scene,
                                        const std::vector<std::filesystem::path>& model_files,
                                        const LoadOptions& options) {
  LoadContext context(options);
  const std::size_t first = scene.models.size();
  std::vector<ModelSpec> models = scene.models;
  for (const auto& file : model_files) models.push_back(readModel(file, context));
  remapDuplicateNames(models, first, context);
  resolveQualifiedParents(models, first, context);
  context.throwIfDeferred();
  scene.models = std::move(models);
  return context.takeWarnings();
}

}  // namespace ambf_like
