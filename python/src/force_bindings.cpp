// raven_analyze forces for Python: a recording's motor signals read back into the forces behind
// them (docs/forces.md), as one array per column of forces.csv.

#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <optional>

#include "analysis/force_report.hpp"
#include "bindings.hpp"

namespace py = pybind11;

namespace raven_python {

void bindForces(py::module_& m) {
  m.def(
      "estimate_forces",
      [](const std::filesystem::path& rs, const std::optional<std::filesystem::path>& calibration,
         double grip_depth, double grip_spread) {
        const twin::CalibrationProfile profile = twin::CalibrationProfile::load(
            calibration.value_or(twin::CalibrationProfile::shippedFile()));
        const analysis::ForceTable table = analysis::estimateForces(
            rs, profile, twin::GripLever{.depth = grip_depth, .spread = grip_spread});
        py::dict out;
        for (std::size_t c = 0; c < table.names.size(); ++c) {
          py::array_t<double> column(static_cast<py::ssize_t>(table.rows.size()));
          auto view = column.mutable_unchecked<1>();
          for (std::size_t r = 0; r < table.rows.size(); ++r) {
            view(static_cast<py::ssize_t>(r)) = table.rows[r][c];
          }
          out[py::str(table.names[c])] = column;
        }
        return out;
      },
      py::arg("rs"), py::arg("calibration") = py::none(), py::arg("grip_depth") = 0.007,
      py::arg("grip_spread") = 0.002,
      "each tool's force and each jaw's squeeze (N) estimated from an rs recording's motor "
      "signals through the twin's model of the arm, with their sd: a dict of arrays keyed as "
      "raven_analyze forces' forces.csv (time, left_fx, ..., right_jaw2_normal, then <name>_sd); "
      "calibration: a profile (default the shipped one); docs/forces.md");
}

}  // namespace raven_python
