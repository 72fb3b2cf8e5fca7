#pragma once
// Errors and warnings raised while reading model files, each pointing at file, line and key path.

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace common {

/// Where in an input file something was found: file, 1-based line (0 = unknown) and key path.
struct SourceRef {
  std::filesystem::path file;
  int line = 0;
  std::string key_path;

  /// "file:line: key/path" (parts that are unknown are left out).
  std::string str() const;
};

/// One problem found in an input, with its location.
struct LoadIssue {
  SourceRef where;
  std::string message;

  std::string str() const;
};

/// Thrown when input files cannot be turned into a model; carries every issue found.
class LoadError : public std::runtime_error {
 public:
  explicit LoadError(std::vector<LoadIssue> issues);
  LoadError(SourceRef where, std::string message);

  const std::vector<LoadIssue>& issues() const { return issues_; }

 private:
  std::vector<LoadIssue> issues_;
};

}  // namespace common
