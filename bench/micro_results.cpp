// Runs the Google Benchmark micro-benchmarks (micro_bench) as a child process and takes their
// JSON into the report.

#include <fmt/format.h>

#include <fstream>
#include <map>

#include "harness/child_process.hpp"
#include "harness/temp_dir.hpp"
#include "sections.hpp"

namespace bench {

void measureMicro(const BenchSettings& s, Report& report) {
  harness::TempDir dir;
  const auto json = dir.path() / "micro.json";
  harness::ChildProcess run(
      {(s.programs / "bench/micro_bench").string(), "--benchmark_out=" + json.string(),
       "--benchmark_out_format=json", fmt::format("--benchmark_repetitions={}", s.repeat)},
      dir.path() / "micro.log");
  if (run.wait(1800.0) != 0) {
    report.skip("micro", "micro_bench", "it failed");
    return;
  }
  const auto results = nlohmann::json::parse(std::ifstream(json));
  std::map<std::string, std::vector<double>> times;  // per benchmark, us per iteration
  std::map<std::string, std::string> errors;
  for (const auto& b : results.at("benchmarks")) {
    const std::string name = b.at("run_name");
    if (b.value("error_occurred", false)) {
      errors[name] = b.value("error_message", "error");
      continue;
    }
    if (b.value("run_type", "") != "iteration") continue;
    const std::string unit = b.value("time_unit", "ns");
    const double to_us = unit == "ns" ? 1e-3 : unit == "ms" ? 1e3 : unit == "s" ? 1e6 : 1.0;
    times[name].push_back(b.at("real_time").get<double>() * to_us);
  }
  for (const auto& [name, ns] : times) {
    report.add(measured("micro", name, Spread::of(ns), "us", "Google Benchmark, real time"));
  }
  for (const auto& [name, why] : errors) report.skip("micro", name, why);
}

}  // namespace bench
