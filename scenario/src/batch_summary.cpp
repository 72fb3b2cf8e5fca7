#include "scenario/batch_summary.hpp"

namespace scenario {

nlohmann::json summarize(const std::vector<nlohmann::json>& rows) {
  std::size_t complete = 0, placed = 0, lost = 0, timed_out = 0, failed = 0, regrasps = 0;
  RunTiming total;
  for (const nlohmann::json& row : rows) {
    complete += row.at("all_placed").get<bool>() ? 1 : 0;
    placed += row.at("placed").get<std::size_t>();
    lost += row.at("lost").get<std::size_t>();
    regrasps += row.at("regrasps").get<std::size_t>();
    timed_out += row.at("timed_out").get<bool>() ? 1 : 0;
    failed += row.contains("failure") && !row.at("failure").is_null() ? 1 : 0;
    const RunTiming timing = RunTiming::fromJson(row);
    total.sim_time += timing.sim_time;
    total.wall_time += timing.wall_time;
    total.loop_seconds += timing.loop_seconds;
    total.steps += timing.steps;
  }
  nlohmann::json j{{"runs", rows.size()},    {"runs_all_placed", complete},
                   {"rings_placed", placed}, {"rings", rows.size() * 6},
                   {"rings_lost", lost},     {"runs_timed_out", timed_out},
                   {"runs_failed", failed},  {"regrasps", regrasps}};
  total.addTo(j);  // sums, with the rates of the whole set
  return j;
}

nlohmann::json summarize(const std::vector<PegTransferResult>& results) {
  std::vector<nlohmann::json> rows;
  rows.reserve(results.size());
  for (const PegTransferResult& r : results) rows.push_back(r.json());
  return summarize(rows);
}

}  // namespace scenario
