// The peg transfer environment's core for Python (raven_sim.env wraps it in Gymnasium's API):
// reset and step release the GIL, so environments on several threads run in parallel.

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "bindings.hpp"
#include "common/actuation_kind.hpp"
#include "scenario/peg_cameras.hpp"
#include "scenario/peg_transfer_env.hpp"
#include "scenario/task_views.hpp"

namespace py = pybind11;

namespace raven_python {

namespace {

/// An episode's saved state, as Python holds it.
struct SavedEpisode {
  std::shared_ptr<const scenario::PegTransferEnv::State> state;
};

/// The scene's design, the observation's layout and the judgement of a placed ring.
void bindLayouts(py::module_& m) {
  m.def("tool_points", &scenario::PegTransferEnv::toolPoints, py::arg("joints"),
        "both arms' tool points (2 x 3, m) in the peg-transfer scene's world frame, the rings' "
        "frame, for 14 joint values (left arm first); the state's tool poses are the robot's own "
        "report");
  m.def(
      "peg_layout",
      [] {
        const scenario::PegLayout layout;
        py::list jobs;
        for (const scenario::RingJob& job : layout.jobs) {
          py::dict d;
          d["ring"] = job.ring;
          d["arm"] = raven::index(job.arm);
          d["from"] = job.from;
          d["to"] = job.to;
          jobs.append(d);
        }
        py::dict out;
        out["jobs"] = jobs;
        out["board_top"] = layout.geometry.board_top;
        out["ring_radius"] = layout.ring.major_radius;
        out["ring_height"] = 2.0 * layout.ring.half_height;
        out["ring_tube_half_width"] = layout.ring.tube_half_width;
        out["ring_stations"] = layout.ring.stations;
        out["ring_tube_stations"] = layout.ring.tube_stations;
        out["post_height"] = layout.geometry.post_height;
        out["post_radius"] = layout.geometry.post_radius;
        return out;
      },
      "the peg transfer's design values: its six jobs (ring, arm 0 left / 1 right, the start and "
      "target posts' x, y in m, in the order of the state's ring centres), the board's top z, "
      "the rings' centre-line radius, height and tube half-width, the stations the ring is "
      "drawn with around it and around its tube, and the posts' height and radius");
  m.def(
      "task_camera",
      [](int arm) {
        if (arm != 0 && arm != 1)
          throw py::value_error("task_camera: arm is 0 (left) or 1 (right)");
        const viewer::Camera c = scenario::taskCamera(
            scenario::PegLayout{}, arm == 0 ? raven::Arm::Left : raven::Arm::Right);
        py::dict out;
        out["eye"] = Eigen::Vector3d(c.eye());
        out["target"] = c.target;
        out["fov_y"] = c.fov_y;
        return out;
      },
      py::arg("arm"),
      "one arm's task camera (arm 0: left-task, 1: right-task) as designed: its eye and the "
      "point it looks at (m, the rings' frame) and its vertical field of view (rad), the "
      "calibration an RGB-D policy takes its images back into the world with");
  m.def(
      "ring_placed",
      [](const Eigen::Vector3d& centre, const Eigen::Vector2d& post) {
        static const scenario::PegLayout layout;
        bridge::Sighting upright;
        upright.pose.translation() = centre;
        return scenario::restsOn(scenario::RingView(upright, layout.ring), post, layout.geometry);
      },
      py::arg("centre"), py::arg("post"),
      "whether an upright ring centred at `centre` (x, y, z, m) rests threaded on the post at "
      "`post` (x, y): the judgement the environment's reward and the main job make "
      "(scenario::restsOn), for a state that has the rings' centres alone");
  m.def(
      "observation_layout",
      [] {
        py::dict out;
        for (const scenario::observation::Part& part : scenario::observation::kParts) {
          out[part.name] =
              py::make_tuple(py::slice(part.slice.start, part.slice.end(), 1), part.item_size);
        }
        return out;
      },
      "where each part of PegTransferEnv's state sits: {name: (slice, values per item)}, the "
      "items an arm's (left first) or a ring's (ring1..ring6) (scenario/observation_layout.hpp)");
}

/// The environment's core (raven_sim.env wraps it), its steps and saved states.
void bindEnvironment(py::module_& m) {
  using E = scenario::PegTransferEnv;
  py::class_<scenario::PegTransferStep>(m, "PegTransferStep")
      .def_readonly("observation", &scenario::PegTransferStep::observation)
      .def_readonly("reward", &scenario::PegTransferStep::reward)
      .def_readonly("terminated", &scenario::PegTransferStep::terminated)
      .def_readonly("truncated", &scenario::PegTransferStep::truncated)
      .def_readonly("placed", &scenario::PegTransferStep::placed)
      .def_readonly("refused", &scenario::PegTransferStep::refused)
      .def_readonly("faulted", &scenario::PegTransferStep::faulted)
      .def_readonly("failure", &scenario::PegTransferStep::failure);

  py::class_<SavedEpisode>(m, "PegTransferState",
                           "a peg-transfer episode's state (PegTransferCore.save_state)");
  py::class_<E>(m, "PegTransferCore", "the peg transfer, one manual-loop iteration per step")
      .def(py::init([](bool randomize, double time_limit,
                       std::optional<std::filesystem::path> launch_file, const std::string& action,
                       const std::string& control, double period, const std::string& actuation,
                       std::optional<std::filesystem::path> ranges) {
             scenario::PegTransferEnvOptions options;
             options.randomize = randomize;
             if (ranges) options.ranges = scenario::readVariationRanges(*ranges);
             options.time_limit = time_limit;
             if (launch_file) options.launch_file = *launch_file;
             options.action = scenario::envActionNamed(action);
             if (control != "waypoint" && control != "period") {
               throw std::invalid_argument("control is 'waypoint' or 'period', not '" + control +
                                           "'");
             }
             options.control = control == "period" ? scenario::EnvControl::Period
                                                   : scenario::EnvControl::Waypoint;
             options.period = period;
             options.actuation = common::actuationNamed(actuation);
             return std::make_unique<E>(options);
           }),
           py::arg("randomize") = false, py::arg("time_limit") = 240.0,
           py::arg("launch_file") = py::none(), py::arg("action") = "joints",
           py::arg("control") = "waypoint", py::arg("period") = 0.05,
           py::arg("actuation") = "motors", py::arg("ranges") = py::none())
      .def_readonly_static("observation_size", &E::kObservationSize)
      .def_property_readonly(
          "variation", [](const E& e) { return e.variation().json().dump(); },
          "the episode's scene draw (JSON): the seed and each varied value, or nominal")
      .def_property_readonly("action_size", &E::actionSize)
      .def(
          "reset",
          [](E& e, std::uint64_t seed) {
            py::gil_scoped_release release;
            return e.reset(seed);
          },
          py::arg("seed"))
      .def(
          "step",
          [](E& e, const Eigen::VectorXd& action) {
            py::gil_scoped_release release;
            return e.step(action);
          },
          py::arg("action"), "one action of the environment's kind (joints: 14 targets)")
      .def(
          "step_pad",
          [](E& e, const std::array<double, recording::GamepadState::kCiColumns>& row) {
            const auto pad = recording::GamepadState::fromCiRow(row);
            py::gil_scoped_release release;
            return e.step(pad);
          },
          py::arg("ci_row"), "one pad reading as a ci row (14 values)")
      .def("expert_action", &E::expertAction, py::arg("from_state") = false,
           "the main job's scripted operator's next step, as an action of the environment's "
           "kind; from_state: taken up from the state reached (steps someone else decided)")
      .def("expert_jobs_finished", &E::expertJobsFinished,
           "per arm (left first), the expert's jobs finished, placed or given up (3 once done)")
      .def(
          "save_state",
          [](E& e) {
            py::gil_scoped_release release;
            return SavedEpisode{e.saveState()};
          },
          "the episode's state (the world, the twin, the controller, the expert)")
      .def(
          "restore_state",
          [](E& e, const SavedEpisode& saved) {
            py::gil_scoped_release release;
            e.restoreState(*saved.state);
          },
          py::arg("state"), "back to a state this episode saved")
      .def_property_readonly("action_low", &E::actionLow)
      .def_property_readonly("action_high", &E::actionHigh)
      .def_property_readonly("time", &E::time)
      .def_property_readonly("observation", &E::observation)
      .def_property_readonly("placed", &E::placed)
      .def_property_readonly(
          "twin", [](E& e) -> twin::TwinPlatform& { return e.twin(); },
          py::return_value_policy::reference_internal,
          "the episode's twin (raven_sim.Twin): its raven_state (Tau, DAC), measured_cf, ...; "
          "valid until the next reset");
}

/// An episode's cameras: its named views rendered as arrays.
void bindCameras(py::module_& m) {
  using E = scenario::PegTransferEnv;
  py::class_<scenario::PegCameras>(m, "PegCameras",
                                   "the named views of an episode's world as images (headless)")
      .def(py::init([](E& env, const std::vector<std::string>& views, int width, int height) {
             return std::make_unique<scenario::PegCameras>(env.twin().world(), views, width, height,
                                                           env.variation());
           }),
           py::arg("env"), py::arg("views"), py::arg("width"), py::arg("height"))
      .def(
          "render",
          [](scenario::PegCameras& cameras, E& env, bool rgb, bool depth, bool segmentation) {
            std::vector<viewer::CameraImages> images;
            {
              py::gil_scoped_release release;
              images = cameras.render(env.twin().world(), rgb, depth, segmentation);
            }
            py::list out;
            for (const auto& i : images) {
              const auto h = static_cast<py::ssize_t>(i.height);
              const auto w = static_cast<py::ssize_t>(i.width);
              py::dict d;
              if (rgb) d["rgb"] = py::array_t<std::uint8_t>({h, w, py::ssize_t{3}}, i.rgb.data());
              if (depth) d["depth"] = py::array_t<float>({h, w}, i.depth.data());
              if (segmentation) {
                d["segmentation"] = py::array_t<std::int32_t>(
                    {h, w},
                    std::vector<std::int32_t>(i.segmentation.begin(), i.segmentation.end()).data());
              }
              out.append(d);
            }
            return out;
          },
          py::arg("env"), py::arg("rgb"), py::arg("depth"), py::arg("segmentation"));
}

}  // namespace

void bindPegTransferEnv(py::module_& m) {
  bindLayouts(m);
  bindEnvironment(m);
  bindCameras(m);
}

}  // namespace raven_python
