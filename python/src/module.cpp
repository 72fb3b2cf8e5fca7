// _raven_sim: the twin, the simulator and the recordings in process, for Python (the
// raven_sim package wraps it). Errors keep their C++ messages: file, line and key for model
// files, file and row for recordings.

#include <pybind11/pybind11.h>

#include "ambf_like/step_guard.hpp"
#include "bindings.hpp"
#include "common/load_error.hpp"
#include "recording/recording_io.hpp"

PYBIND11_MODULE(_raven_sim, m) {
  m.doc() = "The Raven-II twin, its simulator and the paper's recordings, in process.";
  pybind11::register_exception<common::LoadError>(m, "LoadError", PyExc_ValueError);
  pybind11::register_exception<recording::RecordingError>(m, "RecordingError", PyExc_ValueError);
  pybind11::register_exception<ambf_like::SimulationDiverged>(m, "SimulationDiverged",
                                                              PyExc_RuntimeError);
  raven_python::bindWorld(m);
  raven_python::bindTwin(m);
  raven_python::bindRecordings(m);
  raven_python::bindForces(m);
  raven_python::bindController(m);
  raven_python::bindPegTransferEnv(m);
  raven_python::bindRobotOverRos(m);
}
