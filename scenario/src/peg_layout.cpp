#include "scenario/peg_layout.hpp"

namespace scenario {

PegLayout::PegLayout(const raven::design::PegSceneDesign& design,
                     const std::optional<Eigen::Isometry3d>& board) {
  Eigen::Isometry3d at = Eigen::Isometry3d::Identity();
  at.translation() << design.board_centre.x(), design.board_centre.y(), design.board_top;
  if (board) at = *board;
  auto post = [&](std::size_t i) -> Eigen::Vector2d {
    const Eigen::Vector2d local = design.posts[i] - design.board_centre;
    return (at * Eigen::Vector3d(local.x(), local.y(), 0.0)).head<2>();
  };
  ring = {.major_radius = design.peg_major_radius,
          .tube_half_width = design.peg_minor_radius,
          .half_height = design.peg_half_height,
          .stations = design.peg_ring_segments};
  geometry.board_top = at.translation().z();
  geometry.post_radius = design.post_radius;
  geometry.post_height = design.post_height;
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    const raven::Arm arm = design.posts[i].x() > 0.0 ? raven::Arm::Left : raven::Arm::Right;
    jobs[i] = RingJob{"peg" + std::to_string(i + 1), arm, post(i), post(i + jobs.size())};
  }
}

PegLayout PegLayout::seen(const bridge::ScenePerception& scene,
                          const raven::design::PegSceneDesign& design) {
  return PegLayout(design, scene.sight(kBoard).pose);
}

std::vector<RingJob> PegLayout::jobsOf(raven::Arm arm) const {
  std::vector<RingJob> out;
  for (const RingJob& job : jobs) {
    if (job.arm == arm) out.push_back(job);
  }
  return out;
}

}  // namespace scenario
