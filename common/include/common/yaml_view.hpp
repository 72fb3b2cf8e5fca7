#pragma once
// A YAML node together with its file and key path, so every read can report where it failed.

#include <yaml-cpp/yaml.h>

#include <Eigen/Geometry>
#include <filesystem>
#include <initializer_list>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

#include "common/load_error.hpp"

namespace common {

/// How checkKeys treats what it finds: unknown keys throw when `strict`, otherwise they and
/// duplicate keys are appended to `warnings`.
struct KeyCheck {
  bool strict = true;
  std::vector<LoadIssue>& warnings;
};

/// Read-only view of one YAML node that knows its file and key path.
class YamlView {
 public:
  /// Parses a whole file. Throws LoadError naming the file (and line) on I/O or syntax errors.
  static YamlView parseFile(const std::filesystem::path& file);

  YamlView(YAML::Node node, std::shared_ptr<const std::filesystem::path> file,
           std::string key_path);

  const std::filesystem::path& file() const { return *file_; }
  SourceRef where() const;
  [[noreturn]] void fail(const std::string& message) const;

  bool isMap() const { return node_.IsMap(); }
  bool isSequence() const { return node_.IsSequence(); }
  bool isNull() const { return node_.IsNull(); }

  bool has(std::string_view key) const;
  /// The value of a required key; a missing key is an error naming this node's path.
  YamlView operator[](std::string_view key) const;
  std::optional<YamlView> find(std::string_view key) const;
  /// Elements of a sequence (error if this is not a sequence).
  std::vector<YamlView> elements() const;
  /// Keys of a mapping in file order (error if this is not a mapping).
  std::vector<std::string> keys() const;
  /// A mapping's values by key, the first of a duplicated key (as find() takes it), in one pass:
  /// yaml-cpp looks a key up by walking the mapping, so a file of 40,000 definitions looked up
  /// one by one takes minutes.
  std::unordered_map<std::string, YamlView> children() const;

  std::string asString() const;
  /// The text lower-cased, for case-insensitive keywords such as shape names.
  std::string asKeyword() const;
  double asDouble() const;  ///< finite numbers only
  int asInt() const;
  bool asBool() const;
  Eigen::Vector3d asXyz() const;  ///< {x, y, z}
  Eigen::Vector3d asRpy() const;  ///< {r, p, y}
  /// {position {x,y,z}, orientation {r,p,y}}, both optional; R = Rz(y) Ry(p) Rx(r).
  Eigen::Isometry3d asPose() const;
  /// A list of exactly `count` numbers (any count when `count` is 0).
  std::vector<double> asDoubleList(std::size_t count = 0) const;
  std::vector<int> asIntList() const;

  double getDouble(std::string_view key, double fallback) const;
  bool getBool(std::string_view key, bool fallback) const;

  /// Reports keys that are not in `known` (error or warning, per the load options) and duplicate
  /// keys (a warning: yaml-cpp, like AMBF, uses the first one).
  void checkKeys(std::span<const std::string_view> known, KeyCheck check) const;
  void checkKeys(std::initializer_list<std::string_view> known, KeyCheck check) const {
    checkKeys(std::span(known.begin(), known.size()), check);
  }
  /// Same for keys that may appear at the top of a file beside identifier mappings.
  void checkSectionKeys(std::initializer_list<std::string_view> known, KeyCheck check) const;

 private:
  int line() const;
  std::string childPath(std::string_view key) const;
  void checkKeysImpl(std::span<const std::string_view> known, bool allow_mappings,
                     KeyCheck check) const;

  YAML::Node node_;
  std::shared_ptr<const std::filesystem::path> file_;
  std::string key_path_;
};

}  // namespace common
