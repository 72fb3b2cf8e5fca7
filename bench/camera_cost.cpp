// What a camera observation costs: frames per second of the peg-transfer scene's overview camera
// rendered headless (EGL) as the learning environment renders it, colour alone and colour, depth
// and segmentation together, at the two sizes learners use.

#include <fmt/format.h>

#include <chrono>

#include "ambf_like/scene_loader.hpp"
#include "raven/platform_profile.hpp"
#include "scenario/peg_cameras.hpp"
#include "sections.hpp"
#include "viewer/viewer.hpp"

namespace bench {

namespace {

const char* kSection = "cameras";
constexpr int kFrames = 100;

}  // namespace

void measureCameras(const BenchSettings& s, Report& report) {
  ambf_like::MeshLibrary meshes;
  const auto scene =
      ambf_like::loadLaunchFile(raven::modelDirectory() / "peg_transfer" / "launch.yaml", {});
  ambf_like::World world(scene.spec, meshes);
  world.step(200);
  for (const auto& [w, h] : {std::pair{128, 96}, std::pair{256, 192}}) {
    std::unique_ptr<scenario::PegCameras> cameras;
    try {
      cameras =
          std::make_unique<scenario::PegCameras>(world, std::vector<std::string>{"overview"}, w, h);
    } catch (const viewer::NoDisplay& e) {
      report.skip(kSection, "camera frames", std::string("no headless OpenGL: ") + e.what());
      return;
    }
    for (const bool all : {false, true}) {
      std::vector<double> rates;
      for (int r = 0; r < s.repeat; ++r) {
        const auto start = std::chrono::steady_clock::now();
        for (int k = 0; k < kFrames; ++k) {
          world.step(1);  // a new instant each frame, as between environment steps
          cameras->render(world, true, all, all);
        }
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        rates.push_back(kFrames / seconds);
      }
      report.add(measured(kSection,
                          fmt::format("overview camera {}x{}, {}", w, h,
                                      all ? "rgb + depth + segmentation" : "rgb"),
                          Spread::of(rates), "frames/s",
                          fmt::format("{} frames a run, {} runs, one physics step between frames "
                                      "(included)",
                                      kFrames, s.repeat)));
    }
  }
}

}  // namespace bench
