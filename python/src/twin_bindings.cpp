// The twin for Python: the same command objects and results as the C++ RavenPlatform, its
// clock, its CRTK-shaped queries, its world.

#include <pybind11/eigen.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "bindings.hpp"
#include "bridge/enable_and_home.hpp"
#include "common/actuation_kind.hpp"
#include "twin/calibration_profile.hpp"
#include "twin/twin_platform.hpp"

namespace py = pybind11;

namespace raven_python {

namespace {

using bridge::Arm;
using bridge::ArmJoints;

Eigen::Isometry3d isometry(const Eigen::Matrix4d& m) {
  Eigen::Isometry3d pose;
  pose.matrix() = m;
  return pose;
}

/// Binds a per-arm command `C` with one value field (its constructor takes arm, value).
template <typename C, typename Value, typename Python = Value>
void bindCommand(py::module_& m, const char* name, Value C::*field, const char* field_name,
                 const char* doc) {
  py::class_<C>(m, name, doc)
      .def(py::init([field](Arm arm, const Python& value) {
             C c{arm, {}};
             if constexpr (std::is_same_v<Value, Eigen::Isometry3d>) {
               c.*field = isometry(value);
             } else {
               c.*field = value;
             }
             return c;
           }),
           py::arg("arm"), py::arg(field_name))
      .def_readwrite("arm", &C::arm);
}

/// A getter that hands Python its own (writable) copy of a vector field.
template <typename C, typename V>
auto copied(V C::*field) {
  return [field](const C& c) { return V(c.*field); };
}

}  // namespace

namespace {

/// The arms, the state commands and the CRTK motion commands, and a command's answer.
void bindCommands(py::module_& m) {
  py::enum_<Arm>(m, "Arm", "LEFT is the gold arm (arm1), RIGHT the green arm (arm2).")
      .value("LEFT", Arm::Left)
      .value("RIGHT", Arm::Right);
  py::enum_<bridge::StateCommand>(m, "StateCommand")
      .value("ENABLE", bridge::StateCommand::Enable)
      .value("DISABLE", bridge::StateCommand::Disable)
      .value("PAUSE", bridge::StateCommand::Pause)
      .value("RESUME", bridge::StateCommand::Resume)
      .value("HOME", bridge::StateCommand::Home)
      .value("UNHOME", bridge::StateCommand::Unhome);

  bindCommand<bridge::ServoJp, ArmJoints>(m, "ServoJp", &bridge::ServoJp::position, "position",
                                          "absolute joints (CRTK servo_jp), 7 values");
  bindCommand<bridge::ServoJr, ArmJoints>(m, "ServoJr", &bridge::ServoJr::increment, "increment",
                                          "joint increments (CRTK servo_jr)");
  bindCommand<bridge::MoveJp, ArmJoints>(m, "MoveJp", &bridge::MoveJp::goal, "goal",
                                         "a planned joint move; busy until it arrives");
  bindCommand<bridge::ServoCp, Eigen::Isometry3d, Eigen::Matrix4d>(
      m, "ServoCp", &bridge::ServoCp::pose, "pose", "an absolute tool pose (4x4), base frame");
  bindCommand<bridge::ServoCr, Eigen::Isometry3d, Eigen::Matrix4d>(
      m, "ServoCr", &bridge::ServoCr::increment, "increment", "a tool-pose increment (4x4)");
  bindCommand<bridge::ServoJawJp, double>(m, "ServoJawJp", &bridge::ServoJawJp::opening, "opening",
                                          "the grasper opening jaw1 + jaw2 (rad)");
  bindCommand<bridge::ServoJawJr, double>(m, "ServoJawJr", &bridge::ServoJawJr::increment,
                                          "increment", "a grasper-opening increment (rad)");

  py::class_<bridge::CommandResult>(m, "CommandResult", "Taken, or refused with the reason.")
      .def_readonly("ok", &bridge::CommandResult::accepted)
      .def_readonly("note", &bridge::CommandResult::note)
      .def("__bool__", [](const bridge::CommandResult& r) { return r.accepted; })
      .def("__repr__", [](const bridge::CommandResult& r) {
        return std::string(r.accepted ? "<taken" : "<refused") +
               (r.note.empty() ? "" : ": " + r.note) + ">";
      });
}

/// What a platform reports: its status, joints, grasp forces and raven_state.
void bindReadings(py::module_& m) {
  py::class_<bridge::OperatingStatus>(m, "OperatingStatus")
      .def_property_readonly(
          "state", [](const bridge::OperatingStatus& s) { return std::string(wireName(s.state)); })
      .def_readonly("is_homed", &bridge::OperatingStatus::is_homed)
      .def_readonly("is_busy", &bridge::OperatingStatus::is_busy)
      .def_property_readonly("ready", &bridge::OperatingStatus::ready);

  py::class_<bridge::JointSample>(m, "JointSample", "measured_js / setpoint_js of one arm")
      .def_readonly("time", &bridge::JointSample::time)
      .def_property_readonly("position", copied(&bridge::JointSample::position))
      .def_property_readonly("velocity", copied(&bridge::JointSample::velocity))
      .def_property_readonly("effort", copied(&bridge::JointSample::effort));

  py::class_<bridge::JawForces>(m, "JawForces")
      .def_property_readonly("normal", copied(&bridge::JawForces::normal))
      .def_property_readonly("friction", copied(&bridge::JawForces::friction))
      .def_readonly("contacts", &bridge::JawForces::contacts);
  py::class_<bridge::GrasperForces>(m, "GrasperForces", "measured_cf: what the jaws push on (N)")
      .def_readonly("time", &bridge::GrasperForces::time)
      .def_readonly("jaws", &bridge::GrasperForces::jaws)
      .def_property_readonly("force", copied(&bridge::GrasperForces::force))
      .def_property_readonly("torque", copied(&bridge::GrasperForces::torque));

  py::class_<bridge::RavenStateSnapshot>(m, "RavenState", "one raven_state sample (robot units)")
      .def_readonly("time", &bridge::RavenStateSnapshot::time)
      .def_readonly("runlevel", &bridge::RavenStateSnapshot::runlevel)
      .def_readonly("sublevel", &bridge::RavenStateSnapshot::sublevel)
      .def_readonly("pos", &bridge::RavenStateSnapshot::pos)
      .def_readonly("jpos", &bridge::RavenStateSnapshot::jpos)
      .def_readonly("jpos_d", &bridge::RavenStateSnapshot::jpos_d)
      .def_readonly("mpos", &bridge::RavenStateSnapshot::mpos)
      .def_readonly("mvel", &bridge::RavenStateSnapshot::mvel)
      .def_readonly("mpos_d", &bridge::RavenStateSnapshot::mpos_d)
      .def_readonly("tau", &bridge::RavenStateSnapshot::tau)
      .def_readonly("dac_val", &bridge::RavenStateSnapshot::dac_val)
      .def_readonly("grasp_d", &bridge::RavenStateSnapshot::grasp_d);
}

/// The in-process twin as a RavenPlatform.
void bindTwinPlatform(py::module_& m) {
  using T = twin::TwinPlatform;
  py::class_<T>(m, "Twin", "The in-process Raven-II twin on the simulated clock (RavenPlatform).")
      .def(py::init([](std::optional<std::filesystem::path> launch_file, const std::string& profile,
                       const std::string& actuation,
                       std::optional<std::filesystem::path> calibration, bool strict) {
             twin::TwinOptions options;
             if (launch_file) options.launch_file = *launch_file;
             options.profile = profile;
             options.load.strict = strict;
             if (common::actuationNamed(actuation) == common::ActuationKind::Motors) {
               (calibration ? twin::CalibrationProfile::load(*calibration)
                            : twin::CalibrationProfile::shipped())
                   .applyTo(options);
             }
             py::gil_scoped_release release;
             return std::make_unique<T>(options);
           }),
           py::arg("launch_file") = py::none(), py::arg("profile") = "physical",
           py::arg("actuation") = "motors", py::arg("calibration") = py::none(),
           py::arg("strict") = false,
           "launch_file: a scene with the robot (default: our Raven-II alone); actuation: "
           "'motors' (the Raven-II's motor-level actuation, fitted) or 'ideal' (ideal joint "
           "servos); calibration: a raven_calibrate profile (YAML; default: the shipped one)")
      .def("send", [](T& t, bridge::StateCommand c) { return t.send(c); })
      .def("send", [](T& t, const bridge::ServoJp& c) { return t.send(c); })
      .def("send", [](T& t, const bridge::ServoJr& c) { return t.send(c); })
      .def("send", [](T& t, const bridge::MoveJp& c) { return t.send(c); })
      .def("send", [](T& t, const bridge::ServoCp& c) { return t.send(c); })
      .def("send", [](T& t, const bridge::ServoCr& c) { return t.send(c); })
      .def("send", [](T& t, const bridge::ServoJawJp& c) { return t.send(c); })
      .def("send", [](T& t, const bridge::ServoJawJr& c) { return t.send(c); })
      .def(
          "advance",
          [](T& t, double seconds) {
            py::gil_scoped_release release;
            t.advance(seconds);
          },
          py::arg("seconds"), "runs that many 1 ms robot cycles (the GIL released)")
      .def(
          "enable_and_home",
          [](T& t, double timeout) {
            py::gil_scoped_release release;
            bridge::enableAndHome(t, timeout);
          },
          py::arg("timeout") = 30.0, "enables, sends the robot's home and waits until ready")
      .def_property_readonly("now", &T::now)
      .def_property_readonly("operating_status", &T::operatingStatus)
      .def("measured_js", &T::measuredJs, py::arg("arm"))
      .def("setpoint_js", &T::setpointJs, py::arg("arm"))
      .def(
          "measured_cp", [](const T& t, Arm arm) { return t.measuredCp(arm).pose.matrix(); },
          py::arg("arm"), "4x4 tool pose in the arm's base frame")
      .def(
          "setpoint_cp", [](const T& t, Arm arm) { return t.setpointCp(arm).pose.matrix(); },
          py::arg("arm"))
      .def("measured_cf", &T::measuredCf, py::arg("arm"))
      .def("raven_state", &T::ravenState)
      .def_property_readonly(
          "world",
          // keep_alive must sit on the getter itself: the World keeps its twin alive.
          py::cpp_function(
              [](T& t) {
                return WorldHandle{nullptr, &t.world(), {}};
              },
              py::keep_alive<0, 1>()),
          "the twin's simulation (it keeps the twin alive)");
}

}  // namespace

void bindTwin(py::module_& m) {
  bindCommands(m);
  bindReadings(m);
  bindTwinPlatform(m);
}

}  // namespace raven_python
