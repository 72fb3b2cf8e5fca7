#include "scenario/batch_summary.hpp"

namespace scenario {

void RunTotals::add(const nlohmann::json& row) {
  ++runs_;
  complete_ += row.at("all_placed").get<bool>() ? 1 : 0;
  placed_ += row.at("placed").get<std::size_t>();
  lost_ += row.at("lost").get<std::size_t>();
  regrasps_ += row.at("regrasps").get<std::size_t>();
  timed_out_ += row.at("timed_out").get<bool>() ? 1 : 0;
  failed_ += row.contains("failure") && !row.at("failure").is_null() ? 1 : 0;
  const RunTiming timing = RunTiming::fromJson(row);
  time_.sim_time += timing.sim_time;
  time_.wall_time += timing.wall_time;
  time_.loop_seconds += timing.loop_seconds;
  time_.steps += timing.steps;
}

nlohmann::json RunTotals::json() const {
  nlohmann::json j{{"runs", runs_},           {"runs_all_placed", complete_},
                   {"rings_placed", placed_}, {"rings", runs_ * 6},
                   {"rings_lost", lost_},     {"runs_timed_out", timed_out_},
                   {"runs_failed", failed_},  {"regrasps", regrasps_}};
  time_.addTo(j);  // sums, with the rates of the whole set
  return j;
}

nlohmann::json summarize(const std::vector<nlohmann::json>& rows) {
  RunTotals totals;
  for (const nlohmann::json& row : rows) totals.add(row);
  return totals.json();
}

nlohmann::json summarize(const std::vector<PegTransferResult>& results) {
  std::vector<nlohmann::json> rows;
  rows.reserve(results.size());
  for (const PegTransferResult& r : results) rows.push_back(r.json());
  return summarize(rows);
}

}  // namespace scenario
