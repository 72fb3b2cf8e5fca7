// raven_sim's cost from Python: bench/python_step_bench.py as a child process (Debian's
// python3, the build's python/ on its path), its JSON taken into the report.

#include <fmt/format.h>
#include <stdlib.h>

#include "child_output.hpp"
#include "sections.hpp"

namespace bench {

namespace {

constexpr const char* kSection = "python";

}  // namespace

void measurePython(const BenchSettings& s, Report& report) {
  setenv("PYTHONPATH", (s.programs / "python").c_str(), 1);
  const auto lines = outputLinesOf(
      {"/usr/bin/python3", RAVEN_PYTHON_BENCH, "--repeat", std::to_string(s.repeat)}, 3600.0);
  if (!lines) {
    report.skip(kSection, "raven_sim", "python_step_bench.py failed");
    return;
  }
  // The last line is the JSON; spdlog's lines from the twin come before it.
  std::string last;
  for (const std::string& line : *lines) {
    if (!line.empty() && line.front() == '{') last = line;
  }
  const auto r = nlohmann::json::parse(last);
  const auto python = r.at("python_us").get<std::vector<double>>();
  const auto cpp = r.at("cpp_us").get<std::vector<double>>();
  std::vector<double> ratio;
  for (std::size_t i = 0; i < python.size(); ++i) ratio.push_back(python[i] / cpp[i]);
  const std::string how = fmt::format(
      "our Raven-II alone, homed; {} cycles per run, alternating with the same cycles in one "
      "C++ call (Twin.advance), {} runs",
      r.at("cycles").get<int>(), python.size());
  report.add(atMost(kSection, "one 1 ms step per Python call / the same steps in C++",
                    Spread::of(ratio), "x", 1.10, how));
  report.add(measured(kSection, "twin step from Python, one call per 1 ms", Spread::of(python),
                      "us", how));
  report.add(measured(kSection, "twin step in C++ (one call for all)", Spread::of(cpp), "us", how));
  for (const auto& [n, v] : r.at("vector").items()) {
    const std::string note = fmt::format(
        "VectorPegTransferEnv, randomised scenes, {} expert steps each, threads (GIL released)",
        r.at("env_steps").get<int>());
    report.add(measured(kSection, fmt::format("{} peg-transfer environment(s) at once", n),
                        Spread::of(v.at("steps_per_s").get<std::vector<double>>()), "env steps/s",
                        note));
    report.add(measured(kSection, fmt::format("{} environment(s): robot time", n),
                        Spread::of(v.at("robot_s_per_s").get<std::vector<double>>()), "x real time",
                        "summed over the environments"));
  }
  const auto& record = r.at("record");
  const double one = record.at("seconds").at("1").get<double>();
  const double two = record.at("seconds").at("2").get<double>();
  const std::string demos = fmt::format(
      "learn record, {} demonstrations of {} steps, randomised scenes; one worker {:.0f} s, two "
      "{:.0f} s",
      record.at("demos").get<int>(), record.at("steps").get<int>(), one, two);
  report.add(atMost(kSection, "recording on two workers / on one", Spread::of({two / one}), "x",
                    0.6, demos));
}

}  // namespace bench
