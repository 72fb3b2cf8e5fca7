#include "scenario/batch_merge.hpp"

#include <algorithm>
#include <fstream>
#include <map>
#include <set>

#include "scenario/batch_summary.hpp"

namespace scenario {

namespace {

/// Why `row` is not a run of this shard with the fields a summary reads, or empty.
std::string rowProblem(const nlohmann::json& row, const std::set<std::uint64_t>& seeds,
                       const Shard& shard) {
  if (!row.is_object() || !row.contains("seed") || !row["seed"].is_number_unsigned()) {
    return "not a run's JSON object with a seed";
  }
  const auto seed = row["seed"].get<std::uint64_t>();
  if (!seeds.contains(seed)) {
    return "seed " + std::to_string(seed) + " is not in shard " + shard.text() +
           " of this batch's plan";
  }
  try {
    summarize(std::vector<nlohmann::json>{row});  // every field the totals read is there
  } catch (const nlohmann::json::exception& e) {
    return "seed " + std::to_string(seed) + ": " + e.what();
  }
  return {};
}

}  // namespace

ShardCheck checkShard(const BatchPlan& plan, std::size_t index, const std::filesystem::path& dir) {
  ShardCheck check{plan.shard(index), plan.shard(index).runsFile(dir), {}, {}, {}};
  const auto wanted = seedsOf(plan.first_seed, plan.runs, check.shard);
  const std::set<std::uint64_t> seeds(wanted.begin(), wanted.end());
  std::map<std::uint64_t, std::size_t> line_of;  // finished seed -> its line
  std::ifstream in(check.file);
  if (!in) check.problems.push_back("no results file");
  std::string text;
  for (std::size_t line = 1; std::getline(in, text); ++line) {
    if (text.empty()) continue;
    const nlohmann::json row = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
    const std::string at = "line " + std::to_string(line) + ": ";
    if (row.is_discarded()) {
      check.problems.push_back(at + "not JSON (a run cut off while it was written?)");
      continue;
    }
    if (std::string problem = rowProblem(row, seeds, check.shard); !problem.empty()) {
      check.problems.push_back(at + problem);
      continue;
    }
    if (row.value("stopped", false)) continue;  // cut short: its seed stays missing
    const auto seed = row["seed"].get<std::uint64_t>();
    if (const auto [first, inserted] = line_of.emplace(seed, line); !inserted) {
      check.problems.push_back(at + "seed " + std::to_string(seed) + " again (first on line " +
                               std::to_string(first->second) + ")");
      continue;
    }
    check.rows.push_back(row);
  }
  for (std::uint64_t seed : wanted) {
    if (!line_of.contains(seed)) check.missing.push_back(seed);
  }
  return check;
}

BatchCheck checkBatch(const std::filesystem::path& dir) {
  BatchCheck batch{BatchPlan::read(dir), {}};
  for (std::size_t i = 1; i <= batch.plan.shards; ++i) {
    batch.shards.push_back(checkShard(batch.plan, i, dir));
  }
  return batch;
}

bool BatchCheck::whole() const {
  return std::all_of(shards.begin(), shards.end(), [](const ShardCheck& s) { return s.whole(); });
}

std::vector<std::size_t> BatchCheck::shardsToRerun() const {
  std::vector<std::size_t> rerun;
  for (const ShardCheck& s : shards) {
    if (!s.whole()) rerun.push_back(s.shard.index);
  }
  return rerun;
}

std::vector<nlohmann::json> BatchCheck::rowsBySeed() const {
  std::vector<nlohmann::json> rows;
  for (const ShardCheck& s : shards) rows.insert(rows.end(), s.rows.begin(), s.rows.end());
  std::sort(rows.begin(), rows.end(), [](const nlohmann::json& a, const nlohmann::json& b) {
    return a["seed"].get<std::uint64_t>() < b["seed"].get<std::uint64_t>();
  });
  return rows;
}

nlohmann::json BatchCheck::summary() const {
  const std::vector<nlohmann::json> rows = rowsBySeed();
  nlohmann::json j = summarize(rows);
  j["task"] = "peg_transfer";
  j["first_seed"] = plan.first_seed;
  j["shards"] = plan.shards;
  j["options"] = plan.options;
  j["runs_asked"] = plan.runs;
  j["whole"] = whole();
  j["results"] = rows;
  return j;
}

}  // namespace scenario
