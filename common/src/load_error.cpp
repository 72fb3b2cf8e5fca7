#include "common/load_error.hpp"

#include <sstream>

namespace common {

std::string SourceRef::str() const {
  std::ostringstream out;
  out << (file.empty() ? std::string("<input>") : file.string());
  if (line > 0) out << ':' << line;
  if (!key_path.empty()) out << ": " << key_path;
  return out.str();
}

std::string LoadIssue::str() const {
  return where.str() + ": " + message;
}

namespace {
std::string describe(const std::vector<LoadIssue>& issues) {
  if (issues.size() == 1) return issues.front().str();
  std::ostringstream out;
  out << issues.size() << " problems:";
  for (const auto& issue : issues) out << "\n  " << issue.str();
  return out.str();
}
}  // namespace

LoadError::LoadError(std::vector<LoadIssue> issues)
    : std::runtime_error(describe(issues)), issues_(std::move(issues)) {}

LoadError::LoadError(SourceRef where, std::string message)
    : LoadError(std::vector<LoadIssue>{{std::move(where), std::move(message)}}) {}

}  // namespace common
