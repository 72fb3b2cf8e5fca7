// raven_bench: measures the whole pipeline (loop frequency, controller timing, replay speed, the
// ROS edge, memory, micro-benchmarks), prints a Markdown table and writes JSON.

#include <spdlog/spdlog.h>
#include <sys/utsname.h>

#include <CLI/CLI.hpp>
#include <ctime>
#include <fstream>
#include <set>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "common/number_checks.hpp"
#include "sections.hpp"

namespace {

/// Date, kernel, CPU model and core count, compiler: the "machine" of the results.
nlohmann::json machine() {
  utsname u{};
  uname(&u);
  std::string cpu = "unknown";
  std::ifstream info("/proc/cpuinfo");
  for (std::string line; std::getline(info, line);) {
    if (line.rfind("model name", 0) == 0) {
      cpu = line.substr(line.find(':') + 2);
      break;
    }
  }
  char date[32];
  const std::time_t now = std::time(nullptr);
  std::strftime(date, sizeof date, "%Y-%m-%d", std::gmtime(&now));
  return {{"date", date},
          {"kernel", std::string(u.sysname) + " " + u.release},
          {"cpu", cpu},
          {"cores", std::thread::hardware_concurrency()},
          {"compiler", "GCC " __VERSION__}};
}

}  // namespace

int main(int argc, char** argv) {
  bench::BenchSettings settings;
  settings.shared_data = RAVEN_SHARED_DATA_DIR;
  settings.dense_models = RAVEN_DENSE_MODELS_DIR;
  settings.programs = RAVEN_BUILD_DIR;
  std::string out = "bench_results.json", markdown;
  std::vector<std::string> only;
  using Section = void (*)(const bench::BenchSettings&, bench::Report&);
  const std::vector<std::pair<std::string, Section>> sections{
      {"loop", bench::measureLoopFrequency},    {"ambf", bench::measureAmbfScenes},
      {"controller", bench::measureController}, {"replay", bench::measureReplay},
      {"forces", bench::measureForces},         {"ros", bench::measureRosEdge},
      {"viewer", bench::measureViewer},         {"video", bench::measureVideo},
      {"memory", bench::measureMemory},         {"micro", bench::measureMicro},
      {"python", bench::measurePython},         {"cameras", bench::measureCameras},
      {"snapshots", bench::measureSnapshots},   {"soak", bench::measureSoak},
      {"training", bench::measureTraining},     {"robustness", bench::measurePolicyRobustness}};
  std::vector<std::string> names;
  for (const auto& section : sections) names.push_back(section.first);

  CLI::App app{"Measures the Raven-II twin's pipeline; prints a table and writes JSON"};
  app.add_option("--repeat", settings.repeat, "repetitions of each timed run")
      ->check(common::finiteWithin(1, 100));
  app.add_option("--scene-seconds", settings.scene_seconds,
                 "simulated seconds of the moving peg-transfer scene per run")
      ->check(common::finiteWithin(1.0, 300.0));
  app.add_option("--only", only, "sections to run (default: all, in this order)")
      ->check(CLI::IsMember(names));
  app.add_option("--out", out, "JSON results file");
  app.add_option("--markdown", markdown, "also write the table to this file");
  CLI11_PARSE(app, argc, argv);

  const std::set<std::string> chosen(only.begin(), only.end());
  bench::Report report;
  for (const auto& [name, measure] : sections) {
    if (!chosen.empty() && !chosen.count(name)) continue;
    spdlog::info("measuring: {}", name);
    try {
      measure(settings, report);
    } catch (const std::exception& e) {
      report.skip(name, "(section)", std::string("failed: ") + e.what());
    }
  }
  const auto table = report.markdown();
  std::fputs(table.c_str(), stdout);
  std::ofstream(out) << report.json(machine()).dump(2) << '\n';
  if (!markdown.empty()) std::ofstream(markdown) << table;
  spdlog::info("wrote {}", out);
  return 0;
}
