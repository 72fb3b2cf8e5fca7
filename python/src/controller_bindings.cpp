// The paper's controller for Python: the dual-platform controller over a twin and the session
// that runs its modes (O1-O5), replays ci and rs files and records rs / ci / cf files, exactly
// as raven_controller's command thread does.

#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "bindings.hpp"
#include "controller/session.hpp"
#include "twin/twin_platform.hpp"

namespace py = pybind11;

namespace raven_python {

namespace {

std::vector<recording::GamepadState> padsFrom(
    const py::array_t<double, py::array::c_style | py::array::forcecast>& rows) {
  constexpr auto kColumns = static_cast<py::ssize_t>(recording::GamepadState::kCiColumns);
  if (rows.size() == 0) return {};
  if (rows.ndim() != 2 || rows.shape(1) != kColumns) {
    throw std::invalid_argument("inputs must be N x 14 ci rows");
  }
  std::vector<recording::GamepadState> pads;
  auto view = rows.unchecked<2>();
  for (py::ssize_t i = 0; i < rows.shape(0); ++i) {
    std::array<double, recording::GamepadState::kCiColumns> row{};
    for (py::ssize_t k = 0; k < kColumns; ++k) row[static_cast<std::size_t>(k)] = view(i, k);
    pads.push_back(recording::GamepadState::fromCiRow(row));
  }
  return pads;
}

}  // namespace

void bindController(py::module_& m) {
  using controller::Mode;
  py::enum_<Mode>(m, "Mode", "the paper's operation modes")
      .value("IDLE", Mode::Idle)
      .value("HOMING", Mode::Homing)
      .value("MANUAL", Mode::Manual)
      .value("REPLAY_INPUTS", Mode::ReplayInputs)
      .value("REPLAY_JOINTS", Mode::ReplayJoints)
      .value("SINE_DANCE", Mode::SineDance);

  using C = controller::DualPlatformController;
  py::class_<C>(m, "Controller",
                "the paper's controller driving one twin (raven_controller's core)")
      .def(py::init([](twin::TwinPlatform& twin, double rate, int man_steps,
                       const std::string& mapping, bool paper_deadzone, double iteration_overhead) {
             controller::ControllerOptions options;
             options.rate = rate;
             options.caps.min_steps = man_steps;
             options.scheme = controller::mappingSchemeNamed(mapping);
             options.mapping.deadzone_reads_y_twice = paper_deadzone;
             options.iteration_overhead = iteration_overhead;
             return std::make_unique<C>(
                 std::vector<controller::PlatformSlot>{
                     {"twin", &twin, controller::CommandStyle::ServoJr}},
                 options);
           }),
           py::arg("twin"), py::arg("rate") = 500.0, py::arg("man_steps") = 10,
           py::arg("mapping") = "m2", py::arg("paper_deadzone") = false,
           py::arg("iteration_overhead") = 0.0, py::keep_alive<1, 2>(),
           "raven_controller's defaults; the twin must be ready (Twin.enable_and_home)");

  using S = controller::ControllerSession;
  py::class_<S>(m, "ControllerSession", "modes, replays and recordings, one turn at a time")
      .def(py::init([](C& control,
                       const py::array_t<double, py::array::c_style | py::array::forcecast>& inputs,
                       const std::filesystem::path& out_dir, const std::string& record_name,
                       bool end_after_replay) {
             controller::SessionInputs session_inputs;
             session_inputs.inputs = padsFrom(inputs);
             controller::SessionOptions options;
             options.out_dir = out_dir;
             options.record_name = record_name;
             options.end_after_replay = end_after_replay;
             return std::make_unique<S>(control, std::move(session_inputs), options);
           }),
           py::arg("controller"), py::arg("inputs") = py::array_t<double>(),
           py::arg("out_dir") = "recordings", py::arg("record_name") = "raven",
           py::arg("end_after_replay") = true, py::keep_alive<1, 2>(),
           "inputs: ci rows (read_ci) for O3")
      .def("select", &S::select, py::arg("mode"))
      .def("start_recording", &S::startRecording)
      .def("stop_recording", &S::stopRecording)
      .def(
          "turn",
          [](S& s) {
            py::gil_scoped_release release;
            return s.turn();
          },
          "one iteration of the mode; False once the session is over")
      .def(
          "run",
          [](S& s) {
            py::gil_scoped_release release;
            std::size_t turns = 0;
            while (s.turn()) ++turns;
            return turns;
          },
          "turns until the session is over; returns how many")
      .def_property_readonly("recordings", &S::recordings);
}

}  // namespace raven_python
