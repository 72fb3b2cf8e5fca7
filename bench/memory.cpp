// Peak resident size of the main job (GNU time's account of the finished run) and of the twin
// node (its VmHWM while it serves).

#include <fmt/format.h>

#include <fstream>
#include <thread>

#include "harness/child_process.hpp"
#include "harness/ros_master.hpp"
#include "harness/temp_dir.hpp"
#include "sections.hpp"

namespace bench {

void measureMemory(const BenchSettings& s, Report& report) {
  const char* kSection = "memory";
  harness::TempDir dir;
  {
    // GNU time reports the job's own peak: it forks the job from its own small image, whereas a
    // child of this process would start from this process's peak (Linux carries it over exec).
    const auto peak_file = dir.path() / "main_job_peak_kib";
    harness::ChildProcess run({"/usr/bin/time", "-f", "%M", "-o", peak_file.string(),
                               (s.programs / "scenario/raven_peg_transfer").string(), "--record",
                               "no", "--out", (dir.path() / "out").string(), "-q"},
                              dir.path() / "main_job.log");
    long peak_kib = -1;
    if (run.wait(600.0) == 0) std::ifstream(peak_file) >> peak_kib;
    if (peak_kib > 0) {
      report.add(measured(kSection, "main job (peg transfer, whole run)",
                          Spread::of({peak_kib / 1024.0}), "MiB",
                          "/usr/bin/time -f %M raven_peg_transfer"));
    } else {
      report.skip(kSection, "main job", "it failed; see " + (dir.path() / "main_job.log").string());
    }
  }
  harness::RosMaster master;
  harness::ChildProcess node({(s.programs / "twin/ros/raven_twin_node").string()},
                             dir.path() / "node.log");
  std::this_thread::sleep_for(std::chrono::seconds(10));  // serving at 1 kHz meanwhile
  const long peak_kib = node.peakResidentKiB();
  node.stop();
  if (peak_kib > 0) {
    report.add(measured(kSection, "twin node (Raven-II, serving at 1 kHz for 10 s)",
                        Spread::of({peak_kib / 1024.0}), "MiB",
                        "raven_twin_node, default model: VmHWM after 10 s"));
  } else {
    report.skip(kSection, "twin node", "it was not running after 10 s; see node.log");
  }
}

}  // namespace bench
