#include "common/file_problem.hpp"

#include <system_error>

namespace common {

std::string fileProblem(const std::filesystem::path& file) {
  std::error_code error;
  const auto status = std::filesystem::status(file, error);
  if (status.type() == std::filesystem::file_type::not_found) return "file not found";
  if (error) return "cannot be read: " + error.message();
  if (status.type() != std::filesystem::file_type::regular) {
    return "not a regular file (a directory, a pipe or a device)";
  }
  return {};
}

}  // namespace common
