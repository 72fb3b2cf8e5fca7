#include "scenario/peg_layout.hpp"

namespace scenario {

std::string ringName(std::size_t i) {
  return "ring" + std::to_string(i + 1);
}

std::string legacyRingName(std::size_t i) {
  return "peg" + std::to_string(i + 1);
}

std::optional<std::size_t> ringIndexOf(const std::string& body) {
  for (std::size_t i = 0; i < raven::design::PegSceneDesign{}.ring_count; ++i) {
    if (body == ringName(i) || body == legacyRingName(i)) return i;
  }
  return std::nullopt;
}

namespace {

/// Whether `scene` has a sighting of `name`.
bool sees(const bridge::ScenePerception& scene, const std::string& name) {
  try {
    scene.sight(name);
    return true;
  } catch (const bridge::PerceptionError&) {
    return false;
  }
}

}  // namespace

PegLayout::PegLayout(const raven::design::PegSceneDesign& design,
                     const std::optional<Eigen::Isometry3d>& board) {
  Eigen::Isometry3d at = Eigen::Isometry3d::Identity();
  at.translation() << design.board_centre.x(), design.board_centre.y(), design.board_top;
  if (board) at = *board;
  auto post = [&](std::size_t i) -> Eigen::Vector2d {
    const Eigen::Vector2d local = design.posts[i] - design.board_centre;
    return (at * Eigen::Vector3d(local.x(), local.y(), 0.0)).head<2>();
  };
  ring = {.major_radius = design.ring_major_radius,
          .tube_half_width = design.ring_minor_radius,
          .half_height = design.ring_half_height,
          .stations = design.ring_segments,
          .tube_stations = design.ring_tube_segments};
  geometry.board_top = at.translation().z();
  geometry.post_radius = design.post_radius;
  geometry.post_height = design.post_height;
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    const raven::Arm arm = design.posts[i].x() > 0.0 ? raven::Arm::Left : raven::Arm::Right;
    jobs[i] = RingJob{ringName(i), arm, post(i), post(i + jobs.size())};
  }
}

PegLayout PegLayout::seen(const bridge::ScenePerception& scene,
                          const raven::design::PegSceneDesign& design) {
  PegLayout layout(design, scene.sight(kBoard).pose);
  if (!sees(scene, ringName(0)) && sees(scene, legacyRingName(0))) {
    for (std::size_t i = 0; i < layout.jobs.size(); ++i) layout.jobs[i].ring = legacyRingName(i);
  }
  return layout;
}

std::vector<RingJob> PegLayout::jobsOf(raven::Arm arm) const {
  std::vector<RingJob> out;
  for (const RingJob& job : jobs) {
    if (job.arm == arm) out.push_back(job);
  }
  return out;
}

}  // namespace scenario
