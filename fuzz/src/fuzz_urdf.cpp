// Fuzz target: a URDF file read by the model loader (urdfdom, behind the project's nesting
// bound). A LoadError is the right answer to a bad file; a crash, hang or sanitizer report is a
// finding.

#include <cstdint>

#include "ambf_like/scene_loader.hpp"
#include "fuzz_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto file = fuzz::asFile(data, size, "robot.urdf");
  try {
    ambf_like::loadModelFiles({file});
  } catch (const ambf_like::LoadError&) {
  }
  return 0;
}
