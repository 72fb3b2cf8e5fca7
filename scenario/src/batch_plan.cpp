#include "scenario/batch_plan.hpp"

#include <algorithm>
#include <array>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <string_view>

namespace scenario {

namespace {

/// Options the plan sets for every shard itself.
constexpr std::array<std::string_view, 5> kPlanOwned{"--seed", "--runs", "--shard", "--out",
                                                     "--jsonl"};
/// Options that make no sense for a batch on a scheduler: a single run or a window.
constexpr std::array<std::string_view, 6> kNotForBatches{"--task",     "--gui",      "-g",
                                                         "--show_gui", "--snapshot", "--help"};

/// "--seed=3" names "--seed".
std::string_view optionName(std::string_view argument) {
  return argument.substr(0, argument.find('='));
}

bool isOneOf(std::string_view name, const auto& list) {
  return std::find(list.begin(), list.end(), name) != list.end();
}

/// The whole number >= 0 at `key`: nlohmann's get<> converts 1e300 and -5 to counts without a
/// word.
std::uint64_t wholeNumber(const nlohmann::json& j, const char* key) {
  const nlohmann::json& value = j.at(key);
  if (!value.is_number_unsigned()) {
    throw std::invalid_argument(std::string(key) + ": " + value.dump() +
                                " is not a whole number >= 0");
  }
  return value.get<std::uint64_t>();
}

}  // namespace

void BatchPlan::validate() const {
  if (runs == 0) throw std::invalid_argument("a batch needs at least one run");
  if (runs > kMostRuns) {
    throw std::invalid_argument("runs: " + std::to_string(runs) + " (a batch holds at most " +
                                std::to_string(kMostRuns) + ")");
  }
  if (first_seed > std::numeric_limits<std::uint64_t>::max() - runs) {
    throw std::invalid_argument("first_seed: " + std::to_string(first_seed) +
                                " leaves no room for " + std::to_string(runs) + " seeds");
  }
  if (shards == 0 || shards > runs) {
    throw std::invalid_argument("shards: " + std::to_string(shards) + " for " +
                                std::to_string(runs) + " runs (needs 1 <= shards <= runs)");
  }
  for (const std::string& option : options) {
    const std::string_view name = optionName(option);
    if (isOneOf(name, kPlanOwned)) {
      throw std::invalid_argument("option " + std::string(name) +
                                  ": the batch plan sets it for every shard");
    }
    if (isOneOf(name, kNotForBatches)) {
      throw std::invalid_argument("option " + std::string(name) + ": not for a batch of runs");
    }
  }
}

std::vector<std::string> BatchPlan::shardArguments(std::size_t index,
                                                   const std::filesystem::path& dir) const {
  std::vector<std::string> args{
      "--seed",  std::to_string(first_seed), "--runs", std::to_string(runs),
      "--shard", shard(index).text(),        "--out",  dir.string()};
  args.insert(args.end(), options.begin(), options.end());
  return args;
}

nlohmann::json BatchPlan::json() const {
  return {{"task", "peg_transfer"},
          {"first_seed", first_seed},
          {"runs", runs},
          {"shards", shards},
          {"options", options}};
}

BatchPlan BatchPlan::read(const std::filesystem::path& dir) {
  const std::filesystem::path file = dir / kFileName;
  std::ifstream in(file);
  if (!in) {
    throw std::runtime_error(file.string() + ": no batch plan here (raven_batch plan writes it)");
  }
  try {
    const nlohmann::json j = nlohmann::json::parse(in);
    BatchPlan plan;
    plan.first_seed = wholeNumber(j, "first_seed");
    plan.runs = wholeNumber(j, "runs");
    plan.shards = wholeNumber(j, "shards");
    plan.options = j.at("options").get<std::vector<std::string>>();
    plan.validate();
    return plan;
  } catch (const std::exception& e) {
    throw std::runtime_error(file.string() + ": " + e.what());
  }
}

void BatchPlan::write(const std::filesystem::path& dir) const {
  validate();
  std::filesystem::create_directories(dir);
  if (std::filesystem::exists(dir / kFileName) && read(dir) != *this) {
    throw std::runtime_error((dir / kFileName).string() +
                             " holds another batch's plan: use another --out, or remove the "
                             "folder's plan and results first");
  }
  std::ofstream out(dir / kFileName);
  out << json().dump(2) << '\n';
  if (!out) throw std::runtime_error("cannot write " + (dir / kFileName).string());
}

}  // namespace scenario
