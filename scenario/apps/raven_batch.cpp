// raven_batch: a randomised peg-transfer batch on a scheduler. `plan` writes the batch's plan
// into its folder, `run` runs one shard of it (what a Slurm array task or a GNU parallel job
// calls), `merge` checks that every seed came back exactly once and writes the batch's summary,
// or names the shards to run again.

#include <spdlog/fmt/fmt.h>
#include <spdlog/fmt/ranges.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "common/number_checks.hpp"
#include "scenario/batch_merge.hpp"

namespace {

namespace fs = std::filesystem;

/// The exit status of a merge that found shards to run again.
constexpr int kIncomplete = 3;

int plan(const fs::path& dir, const scenario::BatchPlan& plan) {
  plan.write(dir);
  fmt::print("planned {} runs (seeds {}..{}) in {} shards in {}\n", plan.runs, plan.first_seed,
             plan.first_seed + plan.runs - 1, plan.shards, dir.string());
  fmt::print("run shard i (1..{}) with: raven_batch run {} i\n", plan.shards, dir.string());
  return 0;
}

/// The CPUs Slurm gave this task, or null outside Slurm.
const char* slurmTaskCpus() {
  const char* per_task = std::getenv("SLURM_CPUS_PER_TASK");
  return per_task != nullptr ? per_task : std::getenv("SLURM_CPUS_ON_NODE");
}

/// Runs raven_peg_transfer (beside this program unless `program` says) as shard `index`; on a
/// Slurm task with no --threads in the plan, one worker thread per CPU the task was given.
int run(const fs::path& dir, std::size_t index, fs::path program) {
  const scenario::BatchPlan plan = scenario::BatchPlan::read(dir);
  if (index < 1 || index > plan.shards) {
    throw std::invalid_argument(
        fmt::format("shard {}: the plan in {} has shards 1..{}", index, dir.string(), plan.shards));
  }
  if (program.empty())
    program = fs::canonical("/proc/self/exe").parent_path() / "raven_peg_transfer";
  std::vector<std::string> args = plan.shardArguments(index, dir);
  const char* task_cpus = slurmTaskCpus();
  const bool threads_set = std::any_of(plan.options.begin(), plan.options.end(),
                                       [](auto& o) { return o.rfind("--threads", 0) == 0; });
  if (task_cpus != nullptr && !threads_set) args.insert(args.end(), {"--threads", task_cpus});
  std::string program_text = program.string();
  std::vector<char*> argv{program_text.data()};
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::fflush(stdout);
  execv(program_text.c_str(), argv.data());
  throw std::runtime_error("cannot run " + program_text + ": " + std::strerror(errno));
}

int merge(const fs::path& dir) {
  const scenario::BatchCheck batch = scenario::checkBatch(dir);
  const scenario::BatchPlan& plan = batch.plan;
  fmt::print("batch {}: {} runs (seeds {}..{}) in {} shards\n", dir.string(), plan.runs,
             plan.first_seed, plan.first_seed + plan.runs - 1, plan.shards);
  for (const scenario::ShardCheck& shard : batch.shards) {
    if (shard.whole()) continue;
    fmt::print("shard {}: {} of {} runs finished{}{}\n", shard.shard.text(), shard.rows.size(),
               shard.rows.size() + shard.missing.size(),
               shard.missing.empty()
                   ? ""
                   : fmt::format("; missing seeds {}", fmt::join(shard.missing, ", ")),
               shard.problems.empty() ? ""
                                      : fmt::format("; {}: {}", shard.file.filename().string(),
                                                    fmt::join(shard.problems, "; ")));
  }
  if (!batch.whole()) {
    const auto rerun = batch.shardsToRerun();
    fmt::print("incomplete: run shards {} again\n", fmt::join(rerun, ","));
    fmt::print("  Slurm: scripts/slurm/submit-batch.sh --out {} --array {}\n", dir.string(),
               fmt::join(rerun, ","));
    fmt::print("  here:  for i in {}; do raven_batch run {} $i; done\n", fmt::join(rerun, " "),
               dir.string());
    return kIncomplete;
  }
  const nlohmann::json summary = batch.summary();
  const fs::path runs_file = dir / "runs.jsonl", summary_file = dir / "summary.json";
  std::ofstream runs(runs_file);
  for (const nlohmann::json& row : summary["results"]) runs << row.dump() << '\n';
  std::ofstream summary_out(summary_file);
  summary_out << summary.dump(2) << '\n';
  if (!runs || !summary_out) throw std::runtime_error("cannot write into " + dir.string());
  fmt::print(
      "whole: every seed once; {} of {} runs placed all six rings, {} of {} rings placed, {} "
      "lost, {} re-grasps\nwrote {}, {}\n",
      summary["runs_all_placed"].get<std::size_t>(), plan.runs,
      summary["rings_placed"].get<std::size_t>(), summary["rings"].get<std::size_t>(),
      summary["rings_lost"].get<std::size_t>(), summary["regrasps"].get<std::size_t>(),
      summary_file.string(), runs_file.string());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "raven_batch: a peg-transfer batch as shards on a scheduler (Slurm arrays, GNU parallel): "
      "plan it, run a shard, merge and check it"};
  app.require_subcommand(1);

  fs::path dir;
  scenario::BatchPlan batch_plan;
  CLI::App* plan_cmd = app.add_subcommand(
      "plan", "write DIR/batch.json: seeds, shards, and raven_peg_transfer's options after --");
  plan_cmd->add_option("dir", dir, "the batch's folder (shared by every shard)")->required();
  plan_cmd->add_option("--runs", batch_plan.runs, "runs in the batch")
      ->required()
      ->check(common::finiteWithin(1, static_cast<double>(scenario::kMostRuns)));
  plan_cmd->add_option("--shards", batch_plan.shards, "shards (array tasks) to split it in")
      ->required();
  plan_cmd->add_option("--seed", batch_plan.first_seed, "first seed (run k uses seed + k)");
  plan_cmd->add_option("options", batch_plan.options,
                       "raven_peg_transfer options for every run, after --");

  std::size_t index = 0;
  fs::path program;
  CLI::App* run_cmd = app.add_subcommand(
      "run", "run shard INDEX of DIR's plan (raven_peg_transfer --shard INDEX/N)");
  run_cmd->add_option("dir", dir, "the batch's folder")->required()->check(CLI::ExistingDirectory);
  run_cmd->add_option("index", index, "the shard, 1..N (a Slurm array's task id)")->required();
  run_cmd->add_option("--program", program, "raven_peg_transfer to run (default: beside this one)")
      ->check(CLI::ExistingFile);

  CLI::App* merge_cmd = app.add_subcommand(
      "merge",
      "check every seed came back once; write DIR/summary.json and DIR/runs.jsonl, or "
      "name the shards to run again (exit 3)");
  merge_cmd->add_option("dir", dir, "the batch's folder")
      ->required()
      ->check(CLI::ExistingDirectory);

  CLI11_PARSE(app, argc, argv);
  try {
    if (plan_cmd->parsed()) return plan(dir, batch_plan);
    if (run_cmd->parsed()) return run(dir, index, program);
    return merge(dir);
  } catch (const std::exception& e) {
    std::cerr << "raven_batch: " << e.what() << '\n';
    return 2;
  }
}
