#include "child_output.hpp"

#include <fstream>

#include "harness/child_process.hpp"
#include "harness/temp_dir.hpp"

namespace bench {

std::optional<std::vector<std::string>> outputLinesOf(const std::vector<std::string>& argv,
                                                      double timeout) {
  harness::TempDir dir;
  const auto log = dir.path() / "output.log";
  harness::ChildProcess run(argv, log);
  if (run.wait(timeout) != 0) return std::nullopt;
  std::ifstream in(log);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

}  // namespace bench
