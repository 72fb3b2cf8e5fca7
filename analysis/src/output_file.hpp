// A file the analysis writes: opened for writing with ten significant digits, or an error
// naming it.
#pragma once

#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace analysis {

/// Opens `path` for writing (numbers with 10 significant digits); throws std::runtime_error
/// naming it when it cannot be written.
inline std::ofstream openOutputFile(const std::filesystem::path& path) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write " + path.string());
  out.precision(10);
  return out;
}

}  // namespace analysis
