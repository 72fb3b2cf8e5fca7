#include "scenario/peg_cameras.hpp"

#include "raven/platform_profile.hpp"
#include "scenario/task_views.hpp"
#include "viewer/scene_geometry.hpp"

namespace scenario {

namespace {

std::uint32_t bodyLabel(const std::string& name) {
  const bool left = name.rfind("/raven2/left/", 0) == 0;
  const bool right = name.rfind("/raven2/right/", 0) == 0;
  if (!left && !right) return kOther;
  const bool jaw = name.find("jaw") != std::string::npos;
  if (left) return jaw ? kLeftJaws : kLeftArm;
  return jaw ? kRightJaws : kRightArm;
}

}  // namespace

viewer::SceneLabels pegSceneLabels(const ambf_like::World& world,
                                   const viewer::SceneGeometry& geometry, const PegLayout& layout) {
  viewer::SceneLabels labels;
  const viewer::FrameState frame = viewer::FrameState::of(world, false);
  for (std::size_t i = 0; i < geometry.bodies.size(); ++i) {
    const viewer::BodyGeometry& body = geometry.bodies[i];
    if (body.name.find("peg_board") == std::string::npos) {
      labels.bodies.push_back({bodyLabel(body.name)});
      continue;
    }
    std::vector<std::uint32_t> ids;
    const viewer::TriangleMesh& mesh = body.visual;
    for (std::size_t t = 0; t < mesh.triangles(); ++t) {
      const Eigen::Vector3d centre =
          frame.body_poses[i] *
          ((mesh.positions[3 * t] + mesh.positions[3 * t + 1] + mesh.positions[3 * t + 2]) / 3.0f)
              .cast<double>();
      std::uint32_t id = kPlate;
      if (centre.z() > layout.geometry.board_top + 0.0005) {
        double best = 1e9;
        for (std::size_t j = 0; j < layout.jobs.size(); ++j) {
          const double from = (centre.head<2>() - layout.jobs[j].from).norm();
          const double to = (centre.head<2>() - layout.jobs[j].to).norm();
          if (from < best) best = from, id = kFirstStartPost + static_cast<std::uint32_t>(j);
          if (to < best) best = to, id = kFirstTargetPost + static_cast<std::uint32_t>(j);
        }
      }
      ids.push_back(id);
    }
    labels.bodies.push_back(ids);
  }
  for (std::size_t i = 0; i < geometry.soft_bodies.size(); ++i) {
    std::uint32_t id = kOther;
    for (std::size_t j = 0; j < layout.jobs.size(); ++j) {
      if (world.softBody(i).name() == layout.jobs[j].ring) {
        id = kFirstRing + static_cast<std::uint32_t>(j);
      }
    }
    labels.soft_bodies.push_back(id);
  }
  return labels;
}

PegCameras::PegCameras(const ambf_like::World& world, const std::vector<std::string>& views,
                       int width, int height, const SceneVariation& look, const PegLayout& layout) {
  const std::vector<viewer::View> all = pegTransferViews(world, layout);
  for (const std::string& name : views) {
    viewer::View view = viewer::findView(all, name);
    view.camera.target += look.camera_shift;
    view.camera.yaw += look.camera_yaw;
    view.camera.pitch += look.camera_pitch;
    view.camera.distance *= look.camera_distance;
    views_.push_back(view);
  }
  look_.light = static_cast<float>(look.light);
  look_.body_tint = look.body_tint.cast<float>();
  look_.soft_tint = look.ring_tint.cast<float>();
  depth_errors_ = {look.depth_noise, look.depth_scale, look.depth_baseline};
  seed_ = look.seed;
  sensor_ = std::make_unique<viewer::CameraSensor>(
      world, width, height,
      [&](const viewer::SceneGeometry& geometry) {
        return pegSceneLabels(world, geometry, layout);
      },
      raven::ravenVisualSkin());
}

std::vector<viewer::CameraImages> PegCameras::render(const ambf_like::World& world, bool rgb,
                                                     bool depth, bool segmentation) {
  std::vector<viewer::CameraImages> out;
  for (std::size_t i = 0; i < views_.size(); ++i) {
    viewer::CameraImages images =
        sensor_->render(world, views_[i], rgb, depth, segmentation, look_);
    viewer::applyStereoErrors(images.depth, images.width, images.height, views_[i].camera.fov_y,
                              depth_errors_, viewer::depthNoiseKey(seed_, i, world.time()));
    out.push_back(std::move(images));
  }
  return out;
}

}  // namespace scenario
