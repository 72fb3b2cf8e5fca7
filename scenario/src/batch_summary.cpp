#include "scenario/batch_summary.hpp"

namespace scenario {

nlohmann::json summarize(const std::vector<PegTransferResult>& results) {
  std::size_t complete = 0, placed = 0, lost = 0, timed_out = 0, regrasps = 0;
  RunTiming total;
  for (const PegTransferResult& r : results) {
    complete += r.allPlaced() ? 1 : 0;
    placed += r.placed();
    lost += r.lost();
    regrasps += r.regrasps();
    timed_out += r.timed_out ? 1 : 0;
    total.sim_time += r.timing.sim_time;
    total.wall_time += r.timing.wall_time;
    total.loop_seconds += r.timing.loop_seconds;
    total.steps += r.timing.steps;
  }
  nlohmann::json j{{"runs", results.size()}, {"runs_all_placed", complete},
                   {"pegs_placed", placed},  {"pegs", results.size() * 6},
                   {"pegs_lost", lost},      {"runs_timed_out", timed_out},
                   {"regrasps", regrasps}};
  total.addTo(j);  // sums, with the rates of the whole set
  return j;
}

}  // namespace scenario
