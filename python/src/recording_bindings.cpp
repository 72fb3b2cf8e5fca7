// The paper's recordings for Python: ci files as N x 14 arrays, rs files read (any variant)
// and written from the twin's raven_state.

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "bindings.hpp"
#include "recording/recording_io.hpp"

namespace py = pybind11;

namespace raven_python {

void bindRecordings(py::module_& m) {
  constexpr auto kColumns = static_cast<py::ssize_t>(recording::GamepadState::kCiColumns);
  m.def(
      "read_ci",
      [](const std::filesystem::path& path) {
        const auto pads = recording::readCi(path);
        py::array_t<double> out({static_cast<py::ssize_t>(pads.size()), kColumns});
        auto view = out.mutable_unchecked<2>();
        for (std::size_t i = 0; i < pads.size(); ++i) {
          const auto row = pads[i].toCiRow();
          for (py::ssize_t k = 0; k < kColumns; ++k)
            view(static_cast<py::ssize_t>(i), k) = row[static_cast<std::size_t>(k)];
        }
        return out;
      },
      py::arg("path"),
      "a ci file's rows, N x 14 (LX, LY, LT, LB, RX, RY, RT, RB, A, B, X, Y, Back, Start); "
      "raises RecordingError naming file and row");
  m.def("ci_columns", [] {
    std::vector<std::string> out;
    for (auto name : recording::GamepadState::ciColumnNames()) out.emplace_back(name);
    return out;
  });
  m.def(
      "write_ci",
      [](const std::filesystem::path& path,
         const py::array_t<double, py::array::c_style | py::array::forcecast>& rows) {
        if (rows.ndim() != 2 || rows.shape(1) != kColumns) {
          throw std::invalid_argument("write_ci: rows must be N x 14");
        }
        recording::CiWriter writer(path);
        auto view = rows.unchecked<2>();
        for (py::ssize_t i = 0; i < rows.shape(0); ++i) {
          std::array<double, recording::GamepadState::kCiColumns> row{};
          for (py::ssize_t k = 0; k < kColumns; ++k) row[static_cast<std::size_t>(k)] = view(i, k);
          writer.write(recording::GamepadState::fromCiRow(row));
        }
      },
      py::arg("path"), py::arg("rows"));

  py::class_<recording::RsRecording>(m, "RsRecording", "an rs file in memory (any variant)")
      .def_readonly("path", &recording::RsRecording::path)
      .def_readonly("names", &recording::RsRecording::names)
      .def_property_readonly("variant",
                             [](const recording::RsRecording& r) { return r.variant.describe(); })
      .def_property_readonly(
          "rows",
          [](const recording::RsRecording& r) {
            const auto n = static_cast<py::ssize_t>(r.rows.size());
            const auto width = static_cast<py::ssize_t>(r.names.size());
            py::array_t<double> out({n, width});
            auto view = out.mutable_unchecked<2>();
            for (py::ssize_t i = 0; i < n; ++i) {
              for (py::ssize_t k = 0; k < width; ++k)
                view(i, k) = r.rows[static_cast<std::size_t>(i)][static_cast<std::size_t>(k)];
            }
            return out;
          },
          "N x columns, NaN where a field was empty")
      .def("column", &recording::RsRecording::column, py::arg("name"))
      .def("time", &recording::RsRecording::time, py::arg("row"))
      .def("joints", &recording::RsRecording::joints, py::arg("row"), py::arg("arm"),
           "jpos of an arm in the platform's joint convention (rad, m)");
  m.def(
      "read_rs", [](const std::filesystem::path& path) { return recording::readRs(path); },
      py::arg("path"), "reads any rs variant; raises RecordingError naming file and row");

  py::class_<recording::RsWriter>(m, "RsWriter", "writes an rs file, one row per write")
      .def(py::init<const std::filesystem::path&>(), py::arg("path"))
      .def("write", &recording::RsWriter::write, py::arg("state"))
      .def_property_readonly("rows", &recording::RsWriter::rows);
}

}  // namespace raven_python
