#pragma once
// Loader-wide options and the warnings collected while reading one scene.

#include <set>
#include <string>
#include <vector>

#include "ambf_like/load_error.hpp"
#include "ambf_like/load_options.hpp"
#include "common/yaml_view.hpp"

namespace ambf_like::detail {

/// Carries the options of one load and gathers its warnings and deferred errors.
class LoadContext {
 public:
  explicit LoadContext(LoadOptions options) : options_(options) {}

  const LoadOptions& options() const { return options_; }
  void warn(SourceRef where, std::string message);
  /// What AMBF tolerates: a warning, or in a strict load a deferred error.
  void tolerate(SourceRef where, std::string message);
  /// A key AMBF reads but this simulator does not simulate: one note per key and load.
  void acceptedNotSimulated(SourceRef where, const std::string& key);
  /// An error that does not stop reading (so one run reports every missing file); thrown at the
  /// end.
  void defer(SourceRef where, std::string message);
  void throwIfDeferred() const;

  /// How YamlView::checkKeys should treat unknown and duplicate keys in this load.
  common::KeyCheck keyCheck() { return {options_.strict, warnings_}; }

  std::vector<LoadIssue> takeWarnings() { return std::move(warnings_); }

 private:
  LoadOptions options_;
  std::vector<LoadIssue> warnings_;
  std::vector<LoadIssue> errors_;
  std::set<std::string> noted_keys_;
};

}  // namespace ambf_like::detail
