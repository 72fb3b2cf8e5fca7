// Peak resident size of the main job and of the twin node, from the kernel's accounting of the
// finished child process (getrusage's ru_maxrss via wait4).

#include <fmt/format.h>

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
    const auto main_job = (s.programs / "scenario/raven_peg_transfer").string();
    harness::ChildProcess run({main_job, "--grasp-assist", "contact", "--record", "no", "--out",
                               (dir.path() / "out").string(), "-q"},
                              dir.path() / "main_job.log");
    if (run.wait(600.0) == 0) {
      report.add(measured(kSection, "main job (peg transfer, whole run)",
                          Spread::of({run.peakResidentKiB() / 1024.0}), "MiB",
                          "raven_peg_transfer --grasp-assist contact --record no"));
    } else {
      report.skip(kSection, "main job", "it failed; see " + (dir.path() / "main_job.log").string());
    }
  }
  harness::RosMaster master;
  harness::ChildProcess node({(s.programs / "bridge/ros/raven_twin_node").string()},
                             dir.path() / "node.log");
  std::this_thread::sleep_for(std::chrono::seconds(10));  // serving at 1 kHz meanwhile
  node.stop();
  if (node.peakResidentKiB() > 0) {
    report.add(measured(kSection, "twin node (Raven-II, serving at 1 kHz for 10 s)",
                        Spread::of({node.peakResidentKiB() / 1024.0}), "MiB",
                        "raven_twin_node, default model, stopped with SIGINT"));
  } else {
    report.skip(kSection, "twin node", "it did not stop on SIGINT");
  }
}

}  // namespace bench
