#pragma once
// The raven_sim Python module's parts: each adds its classes and functions to the module.

#include <pybind11/pybind11.h>

#include <memory>
#include <string>
#include <vector>

#include "ambf_like/world.hpp"

namespace raven_python {

/// What Python's World holds: a world it loaded (and owns), or a twin's (a view kept alive by
/// the twin's Python object).
struct WorldHandle {
  std::shared_ptr<void> owner;  ///< the loaded scene and world; none for a twin's
  ambf_like::World* world = nullptr;
  std::vector<std::string> warnings;
};

void bindWorld(pybind11::module_& m);
void bindTwin(pybind11::module_& m);
void bindRecordings(pybind11::module_& m);
void bindForces(pybind11::module_& m);
void bindController(pybind11::module_& m);
void bindPegTransferEnv(pybind11::module_& m);
void bindRobotOverRos(pybind11::module_& m);

}  // namespace raven_python
