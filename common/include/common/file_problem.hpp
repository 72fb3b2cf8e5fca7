#pragma once
// Whether a path names a file a reader can open and read to its end, asked without throwing.

#include <filesystem>
#include <string>

namespace common {

/// Why `file` cannot be read as a file: empty when it is a regular file (or a link to one);
/// otherwise "file not found", "not a regular file (a directory, a pipe or a device)" (reading
/// one could block or never end), or the system's reason (e.g. a loop of symbolic links).
std::string fileProblem(const std::filesystem::path& file);

/// fileProblem(file) is empty.
inline bool isReadableFile(const std::filesystem::path& file) {
  return fileProblem(file).empty();
}

}  // namespace common
