// Fuzz target: an AMBF description file (ADF, YAML) read by the model loader. A clear error
// (LoadError) is the right answer to a bad file; a crash, hang or sanitizer report is a finding.

#include <cstdint>

#include "ambf_like/scene_loader.hpp"
#include "fuzz_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto file = fuzz::asFile(data, size, "model.yaml");
  for (bool strict : {false, true}) {
    try {
      ambf_like::loadModelFiles({file}, std::nullopt, {strict});
    } catch (const ambf_like::LoadError&) {
    }
  }
  return 0;
}
