#include "scenario/ring_watch.hpp"

#include <algorithm>
#include <cmath>

namespace scenario {

RingWatch::RingWatch(const PegLayout& layout, RingIntegrity limits)
    : layout_(layout), limits_(limits) {
  for (std::size_t i = 0; i < layout_.jobs.size(); ++i) {
    const RingJob& job = layout_.jobs[i];
    RingOutcome& o = outcomes_[i];
    o.ring = job.ring;
    o.arm = job.arm;
    o.from = job.from;
    o.to = job.to;
  }
}

void RingWatch::observe(const bridge::ScenePerception& scene) {
  const double board = layout_.geometry.board_top;
  for (RingOutcome& o : outcomes_) {
    if (o.lost) continue;
    const RingView ring(scene.sight(o.ring), layout_.ring);
    if (ring.volume_ratio) {
      o.volume_seen = true;
      o.min_volume_ratio = std::min(o.min_volume_ratio, *ring.volume_ratio);
      o.max_volume_ratio = std::max(o.max_volume_ratio, *ring.volume_ratio);
    }
    const double bottom = ring.bottom();
    o.lift = std::max(o.lift, bottom - board);
    o.grasped = o.grasped || layout_.geometry.offTheBoard(bottom);
    if (!ring.finite()) {
      o.lost = true;
      o.loss = "non-finite pose";
    } else if (ring.volume_ratio && std::abs(*ring.volume_ratio - 1.0) > limits_.volume_tolerance) {
      o.lost = true;
      o.loss = "volume " + std::to_string(*ring.volume_ratio) + " of its rest volume";
    } else if (bottom < board - limits_.below_board) {
      o.lost = true;
      o.loss = "fell through the board";
    }
  }
}

std::array<RingOutcome, 6> RingWatch::finish(const bridge::ScenePerception& scene) const {
  auto outcomes = outcomes_;
  for (RingOutcome& o : outcomes) {
    const RingView ring(scene.sight(o.ring), layout_.ring);
    o.final_centre = ring.centre();
    o.miss = (ring.centre().head<2>() - o.to).norm();
    o.placed = !o.lost && restsOn(ring, o.to, layout_.geometry);
  }
  return outcomes;
}

std::size_t RingWatch::lost() const {
  return static_cast<std::size_t>(std::count_if(outcomes_.begin(), outcomes_.end(),
                                                [](const RingOutcome& o) { return o.lost; }));
}

}  // namespace scenario
