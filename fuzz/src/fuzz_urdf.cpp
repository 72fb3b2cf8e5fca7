// Fuzz target: a URDF file read by the model loader (urdfdom, behind the project's nesting
// bound). A LoadError is the right answer to a bad file, and it names a line wherever the file
// has one to name (issue 66); a crash, hang, sanitizer report or a refusal without a line is a
// finding.

#include <cstdint>
#include <string>

#include "ambf_like/scene_loader.hpp"
#include "fuzz_file.hpp"

namespace {

/// Refusals of files that have no element to point at: empty, or no <robot> in them.
bool hasNoLineToName(const std::string& message) {
  return message.find("file is empty") != std::string::npos ||
         message.find("document empty") != std::string::npos ||
         message.find("'robot' element") != std::string::npos;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto file = fuzz::asFile(data, size, "robot.urdf");
  try {
    ambf_like::loadModelFiles({file});
  } catch (const ambf_like::LoadError& error) {
    for (const auto& issue : error.issues()) {
      if (issue.where.line <= 0 && !hasNoLineToName(issue.message)) {
        fuzz::fail("a refusal names no line: " + issue.str());
      }
    }
  }
  return 0;
}
