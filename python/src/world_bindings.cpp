// ambf_like's World for Python: load AMBF launch or model files, step, read bodies, joints,
// soft-body nodes, contacts and sensors, command joints and actuators.

#include <pybind11/eigen.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <memory>

#include "ambf_like/scene_loader.hpp"
#include "ambf_like/world.hpp"
#include "bindings.hpp"

namespace py = pybind11;

namespace raven_python {

namespace {

/// A World's saved state, as Python holds it.
struct SavedWorld {
  std::shared_ptr<const ambf_like::WorldState> state;
};

/// A loaded scene and the world built from it (the world keeps pointers into both).
struct LoadedWorld {
  ambf_like::LoadedScene scene;
  ambf_like::MeshLibrary meshes;
  std::unique_ptr<ambf_like::World> world;

  explicit LoadedWorld(ambf_like::LoadedScene loaded)
      : scene(std::move(loaded)), world(std::make_unique<ambf_like::World>(scene.spec, meshes)) {}
};

/// The nodes straight into one numpy array (Bullet's nodes are not contiguous positions).
py::array_t<double> nodes(const ambf_like::SoftBody& body) {
  const std::size_t count = body.nodeCount();
  py::array_t<double> out({static_cast<py::ssize_t>(count), py::ssize_t{3}});
  auto view = out.mutable_unchecked<2>();
  for (std::size_t i = 0; i < count; ++i) {
    const ambf_like::Vec3 position = body.nodePosition(i);
    for (int k = 0; k < 3; ++k) view(static_cast<py::ssize_t>(i), k) = position(k);
  }
  return out;
}

/// Loads with `load`, then builds the world, without the GIL.
template <typename Load>
WorldHandle build(Load load) {
  py::gil_scoped_release release;
  auto owned = std::make_shared<LoadedWorld>(load());
  WorldHandle handle{owned, owned->world.get(), {}};
  for (const auto& issue : owned->scene.warnings) handle.warnings.push_back(issue.str());
  return handle;
}

py::dict contactDict(const ambf_like::Contact& c) {
  py::dict d;
  d["body_a"] = c.body_a;
  d["body_b"] = c.body_b;
  d["position_on_b"] = c.position_on_b;
  d["normal_on_b"] = c.normal_on_b;
  d["distance"] = c.distance;
  d["normal_impulse"] = c.normal_impulse;
  d["friction_impulse"] = c.friction_impulse;
  d["soft"] = c.soft;
  return d;
}

/// The names of `count` items, `get(i)` giving the i-th.
template <typename Get>
std::vector<std::string> names(std::size_t count, Get get) {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < count; ++i) out.push_back(get(i));
  return out;
}

/// The views of a world's parts: bodies, joints, soft bodies, sensors and actuators.
void bindWorldParts(py::module_& m) {
  py::class_<ambf_like::RigidBody>(m, "RigidBody",
                                   "A rigid body of a World (a view: the World owns it).")
      .def_property_readonly("name", &ambf_like::RigidBody::qualifiedName)
      .def_property_readonly("mass", &ambf_like::RigidBody::mass)
      .def_property_readonly(
          "pose", [](const ambf_like::RigidBody& b) { return b.pose().matrix(); },
          "4x4 homogeneous transform, world frame")
      .def_property_readonly("linear_velocity", &ambf_like::RigidBody::linearVelocity)
      .def_property_readonly("angular_velocity", &ambf_like::RigidBody::angularVelocity);

  py::class_<ambf_like::Joint>(m, "Joint", "A joint of a World (a view).")
      .def_property_readonly("name", &ambf_like::Joint::name)
      .def_property_readonly("position", &ambf_like::Joint::position)
      .def_property_readonly("velocity", &ambf_like::Joint::velocity)
      .def_property_readonly("effort", &ambf_like::Joint::effort)
      .def("command_position", &ambf_like::Joint::commandPosition, py::arg("position"),
           "drives the joint to a position (clamped to its limits); returns the target taken")
      .def("command_velocity", &ambf_like::Joint::commandVelocity, py::arg("velocity"))
      .def("command_effort", &ambf_like::Joint::commandEffort, py::arg("effort"))
      .def("release", &ambf_like::Joint::release);

  py::class_<ambf_like::SoftBody>(m, "SoftBody", "A soft body of a World (a view).")
      .def_property_readonly("name", &ambf_like::SoftBody::qualifiedName)
      .def_property_readonly("nodes", &nodes, "node positions, an N x 3 array (m)")
      .def_property_readonly("center_of_mass", &ambf_like::SoftBody::centerOfMass);

  py::class_<ambf_like::ProximitySensor>(m, "ProximitySensor", "A ray sensor (a view).")
      .def_property_readonly("name", &ambf_like::ProximitySensor::qualifiedName)
      .def_property_readonly("triggered", &ambf_like::ProximitySensor::triggered)
      .def_property_readonly(
          "nearest",
          [](const ambf_like::ProximitySensor& s) -> py::object {
            const auto hit = s.nearest();
            if (!hit) return py::none();
            return py::make_tuple(hit->body, hit->distance, hit->point);
          },
          "(body, distance, point) of the nearest hit, or None");

  py::class_<ambf_like::ConstraintActuator>(m, "ConstraintActuator", "A grip actuator (a view).")
      .def_property_readonly("name", &ambf_like::ConstraintActuator::qualifiedName)
      .def_property_readonly("actuated", &ambf_like::ConstraintActuator::actuated)
      .def(
          "actuate",
          [](ambf_like::ConstraintActuator& a, ambf_like::RigidBody& body) { a.actuate(body); },
          py::arg("body"), py::keep_alive<1, 2>())
      .def("release", &ambf_like::ConstraintActuator::release);
}

}  // namespace

void bindWorld(py::module_& m) {
  bindWorldParts(m);
  py::class_<SavedWorld>(m, "WorldState", "a World's saved state (World.save_state)");
  using W = WorldHandle;
  auto ref = py::return_value_policy::reference_internal;
  py::class_<W>(m, "World", "An ambf_like World: loaded from AMBF's files, or a twin's.")
      .def_static(
          "from_launch",
          [](const std::filesystem::path& launch, bool strict) {
            ambf_like::LoadOptions options;
            options.strict = strict;
            return build([&] { return ambf_like::loadLaunchFile(launch, {}, options); });
          },
          py::arg("launch_file"), py::arg("strict") = false,
          "loads a launch file (its world and every multibody file); raises LoadError "
          "naming file, line and key")
      .def_static(
          "from_models",
          [](const std::vector<std::filesystem::path>& files,
             std::optional<std::filesystem::path> world_file, bool strict) {
            ambf_like::LoadOptions options;
            options.strict = strict;
            return build([&] { return ambf_like::loadModelFiles(files, world_file, options); });
          },
          py::arg("model_files"), py::arg("world_file") = py::none(), py::arg("strict") = false,
          "loads ADF (.yaml) or URDF model files")
      .def(
          "step",
          [](W& w, std::uint64_t count) {
            py::gil_scoped_release release;
            w.world->step(count);
          },
          py::arg("count") = 1, "runs `count` fixed steps (the GIL released)")
      .def(
          "save_state",
          [](W& w) {
            py::gil_scoped_release release;
            return SavedWorld{w.world->saveState()};
          },
          "the world's state between steps (World::saveState): restore_state puts it back")
      .def(
          "restore_state",
          [](W& w, const SavedWorld& saved) {
            py::gil_scoped_release release;
            w.world->restoreState(*saved.state);
          },
          py::arg("state"), "back to a state this world saved; the steps after repeat bit for bit")
      .def_property_readonly("time", [](const W& w) { return w.world->time(); })
      .def_property_readonly("step_size", [](const W& w) { return w.world->stepSize(); })
      .def_readonly("warnings", &W::warnings, "what the loader tolerated (file:line: key: why)")
      .def_property_readonly("bodies",
                             [](const W& w) {
                               return names(w.world->bodyCount(), [&](std::size_t i) {
                                 return w.world->body(i).qualifiedName();
                               });
                             })
      .def_property_readonly("joints",
                             [](const W& w) {
                               return names(w.world->jointCount(), [&](std::size_t i) {
                                 return w.world->joint(i).name();
                               });
                             })
      .def_property_readonly("soft_bodies",
                             [](const W& w) {
                               return names(w.world->softBodyCount(), [&](std::size_t i) {
                                 return w.world->softBody(i).qualifiedName();
                               });
                             })
      .def(
          "body", [](W & w, const std::string& name) -> auto& { return w.world->body(name); }, ref)
      .def(
          "joint", [](W & w, const std::string& name) -> auto& { return w.world->joint(name); },
          ref)
      .def(
          "soft_body",
          [](W & w, const std::string& name) -> auto& { return w.world->softBody(name); }, ref)
      .def(
          "sensor", [](W & w, const std::string& name) -> auto& { return w.world->sensor(name); },
          ref)
      .def(
          "actuator",
          [](W & w, const std::string& name) -> auto& { return w.world->actuator(name); }, ref)
      .def(
          "contacts",
          [](const W& w) {
            py::list out;
            for (const auto& c : w.world->contacts()) out.append(contactDict(c));
            return out;
          },
          "the contact points of the last step, as dicts");
}

}  // namespace raven_python
