#include "scenario/peg_watch.hpp"

#include <algorithm>
#include <cmath>

namespace scenario {

PegWatch::PegWatch(const ambf_like::World& world, const PegLayout& layout, PegIntegrity limits)
    : layout_(layout), limits_(limits) {
  for (std::size_t i = 0; i < layout_.jobs.size(); ++i) {
    const PegJob& job = layout_.jobs[i];
    const auto& body = world.softBody(job.peg);
    pegs_[i] = &body;
    rest_volume_[i] = inspect(body).volume;
    PegOutcome& o = outcomes_[i];
    o.peg = body.name();
    o.arm = job.arm;
    o.from = job.from;
    o.to = job.to;
  }
}

void PegWatch::observe() {
  const double board = layout_.geometry.board_top;
  for (std::size_t i = 0; i < outcomes_.size(); ++i) {
    PegOutcome& o = outcomes_[i];
    if (o.lost) continue;
    const PegState s = inspect(*pegs_[i]);
    const double ratio = s.volume / rest_volume_[i];
    o.min_volume_ratio = std::min(o.min_volume_ratio, ratio);
    o.max_volume_ratio = std::max(o.max_volume_ratio, ratio);
    o.lift = std::max(o.lift, s.bottom - board);
    o.grasped = o.grasped || layout_.geometry.offTheBoard(s.bottom);
    if (!s.finite) {
      o.lost = true;
      o.loss = "non-finite node positions";
    } else if (std::abs(ratio - 1.0) > limits_.volume_tolerance) {
      o.lost = true;
      o.loss = "volume " + std::to_string(ratio) + " of its rest volume";
    } else if (s.bottom < board - limits_.below_board) {
      o.lost = true;
      o.loss = "fell through the board";
    }
  }
}

std::array<PegOutcome, 6> PegWatch::finish() const {
  auto outcomes = outcomes_;
  for (std::size_t i = 0; i < outcomes.size(); ++i) {
    PegOutcome& o = outcomes[i];
    const PegState s = inspect(*pegs_[i]);
    o.final_centre = s.centre;
    o.miss = (s.centre.head<2>() - o.to).norm();
    o.placed = !o.lost && restsOn(*pegs_[i], o.to, layout_.geometry);
  }
  return outcomes;
}

std::size_t PegWatch::lost() const {
  return static_cast<std::size_t>(std::count_if(outcomes_.begin(), outcomes_.end(),
                                                [](const PegOutcome& o) { return o.lost; }));
}

}  // namespace scenario
