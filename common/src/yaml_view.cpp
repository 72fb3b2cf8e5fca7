#include "common/yaml_view.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "common/farthest.hpp"
#include "common/file_problem.hpp"
#include "common/lower_case.hpp"

namespace common {

namespace {

std::size_t editDistance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

std::string suggestion(std::string_view key, std::span<const std::string_view> known) {
  std::string_view best;
  std::size_t best_distance = 3;
  for (auto candidate : known) {
    const auto d = editDistance(key, candidate);
    if (d < best_distance) {
      best = candidate;
      best_distance = d;
    }
  }
  return best.empty() ? std::string() : " (did you mean '" + std::string(best) + "'?)";
}

}  // namespace

YamlView YamlView::parseFile(const std::filesystem::path& file) {
  auto shared_file = std::make_shared<const std::filesystem::path>(file);
  SourceRef where{file, 0, ""};
  if (const auto problem = fileProblem(file); !problem.empty()) {
    throw LoadError(where, problem);
  }
  YAML::Node root;
  try {
    root = YAML::LoadFile(file.string());
  } catch (const YAML::ParserException& e) {
    where.line = e.mark.line + 1;
    throw LoadError(where, "malformed YAML: " + e.msg);
  } catch (const YAML::Exception& e) {
    throw LoadError(where, std::string("cannot read YAML: ") + e.what());
  }
  if (!root.IsDefined() || root.IsNull()) throw LoadError(where, "file is empty");
  if (!root.IsMap()) throw LoadError(where, "expected a YAML mapping at the top level");
  return YamlView(root, shared_file, "");
}

YamlView::YamlView(YAML::Node node, std::shared_ptr<const std::filesystem::path> file,
                   std::string key_path)
    : node_(std::move(node)), file_(std::move(file)), key_path_(std::move(key_path)) {}

int YamlView::line() const {
  const auto mark = node_.Mark();
  return mark.line >= 0 ? mark.line + 1 : 0;
}

SourceRef YamlView::where() const {
  return SourceRef{*file_, line(), key_path_};
}

void YamlView::fail(const std::string& message) const {
  throw LoadError(where(), message);
}

std::string YamlView::childPath(std::string_view key) const {
  return key_path_.empty() ? std::string(key) : key_path_ + "/" + std::string(key);
}

bool YamlView::has(std::string_view key) const {
  if (!node_.IsMap()) return false;
  const YAML::Node& self = node_;
  return self[std::string(key)].IsDefined();
}

std::optional<YamlView> YamlView::find(std::string_view key) const {
  if (!has(key)) return std::nullopt;
  const YAML::Node& self = node_;
  return YamlView(self[std::string(key)], file_, childPath(key));
}

YamlView YamlView::operator[](std::string_view key) const {
  if (!node_.IsMap()) fail("expected a mapping with key '" + std::string(key) + "'");
  auto child = find(key);
  if (!child) fail("missing required key '" + std::string(key) + "'");
  return *child;
}

std::vector<YamlView> YamlView::elements() const {
  if (!node_.IsSequence()) fail("expected a list");
  std::vector<YamlView> out;
  out.reserve(node_.size());
  for (std::size_t i = 0; i < node_.size(); ++i) {
    const YAML::Node& self = node_;
    out.emplace_back(self[i], file_, key_path_ + "[" + std::to_string(i) + "]");
  }
  return out;
}

std::vector<std::string> YamlView::keys() const {
  if (!node_.IsMap()) fail("expected a mapping");
  std::vector<std::string> out;
  for (const auto& entry : node_) out.push_back(entry.first.as<std::string>());
  return out;
}

std::unordered_map<std::string, YamlView> YamlView::children() const {
  if (!node_.IsMap()) fail("expected a mapping");
  std::unordered_map<std::string, YamlView> out;
  for (const auto& entry : node_) {
    const auto key = entry.first.as<std::string>();
    if (!out.contains(key)) out.emplace(key, YamlView(entry.second, file_, childPath(key)));
  }
  return out;
}

std::string YamlView::asString() const {
  if (!node_.IsScalar()) fail("expected a text value");
  return node_.Scalar();
}

std::string YamlView::asKeyword() const {
  return lowerCase(asString());
}

double YamlView::asDouble() const {
  if (!node_.IsScalar()) fail("expected a number");
  double value = 0.0;
  if (!YAML::convert<double>::decode(node_, value)) {
    fail("expected a number, got '" + node_.Scalar() + "'");
  }
  if (!std::isfinite(value)) fail("expected a finite number, got '" + node_.Scalar() + "'");
  return value;
}

int YamlView::asInt() const {
  if (!node_.IsScalar()) fail("expected an integer");
  int value = 0;
  if (!YAML::convert<int>::decode(node_, value)) {
    fail("expected an integer, got '" + node_.Scalar() + "'");
  }
  return value;
}

bool YamlView::asBool() const {
  if (!node_.IsScalar()) fail("expected true or false");
  // YAML 1.1's true/false, yes/no, on/off, y/n in any of their cases (yaml-cpp), and 0/1, as
  // AMBF's own files write them.
  const std::string& text = node_.Scalar();
  if (text == "0" || text == "1") return text == "1";
  bool value = false;
  if (!YAML::convert<bool>::decode(node_, value)) {
    fail("expected a boolean (true/false, yes/no, on/off or 1/0), got '" + text + "'");
  }
  return value;
}

Eigen::Vector3d YamlView::asXyz() const {
  if (!node_.IsMap()) fail("expected {x, y, z}");
  return {(*this)["x"].asDouble(), (*this)["y"].asDouble(), (*this)["z"].asDouble()};
}

Eigen::Vector3d YamlView::asRpy() const {
  if (!node_.IsMap()) fail("expected {r, p, y}");
  return {(*this)["r"].asDouble(), (*this)["p"].asDouble(), (*this)["y"].asDouble()};
}

Eigen::Isometry3d YamlView::asPose() const {
  if (!node_.IsMap()) fail("expected {position, orientation}");
  const Eigen::Vector3d position =
      has("position") ? (*this)["position"].asXyz() : Eigen::Vector3d::Zero();
  if (position.cwiseAbs().maxCoeff() > kFarthestCoordinate) {
    (*this)["position"].fail("position lies beyond +-1e5 m of the origin");
  }
  const Eigen::Vector3d rpy =
      has("orientation") ? (*this)["orientation"].asRpy() : Eigen::Vector3d::Zero();
  // Beyond this an angle (rad) keeps no digit of its turn.
  constexpr double kLargestAngle = 1e6;
  if (rpy.cwiseAbs().maxCoeff() > kLargestAngle) {
    (*this)["orientation"].fail("an angle lies beyond +-1e6 rad");
  }
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = (Eigen::AngleAxisd(rpy.z(), Eigen::Vector3d::UnitZ()) *
                   Eigen::AngleAxisd(rpy.y(), Eigen::Vector3d::UnitY()) *
                   Eigen::AngleAxisd(rpy.x(), Eigen::Vector3d::UnitX()))
                      .toRotationMatrix();
  pose.translation() = position;
  return pose;
}

std::vector<double> YamlView::asDoubleList(std::size_t count) const {
  std::vector<double> out;
  for (const auto& element : elements()) out.push_back(element.asDouble());
  if (count != 0 && out.size() != count) {
    fail("expected " + std::to_string(count) + " numbers, got " + std::to_string(out.size()));
  }
  return out;
}

std::vector<int> YamlView::asIntList() const {
  std::vector<int> out;
  for (const auto& element : elements()) out.push_back(element.asInt());
  return out;
}

double YamlView::getDouble(std::string_view key, double fallback) const {
  auto child = find(key);
  return child ? child->asDouble() : fallback;
}

bool YamlView::getBool(std::string_view key, bool fallback) const {
  auto child = find(key);
  return child ? child->asBool() : fallback;
}

void YamlView::checkKeys(std::span<const std::string_view> known, KeyCheck check) const {
  checkKeysImpl(known, false, check);
}

void YamlView::checkSectionKeys(std::initializer_list<std::string_view> known,
                                KeyCheck check) const {
  checkKeysImpl(std::span(known.begin(), known.size()), true, check);
}

void YamlView::checkKeysImpl(std::span<const std::string_view> known, bool allow_mappings,
                             KeyCheck check) const {
  if (!node_.IsMap()) fail("expected a mapping");
  std::map<std::string, int> first_line;
  for (const auto& entry : node_) {
    const int key_line = entry.first.Mark().line + 1;
    if (!entry.first.IsScalar()) {
      throw LoadError(SourceRef{*file_, key_line, key_path_},
                      "a key must be a name, not a list or a mapping ('? ' starts a complex key)");
    }
    const auto key = entry.first.as<std::string>();
    SourceRef key_where{*file_, key_line, childPath(key)};
    if (auto [it, inserted] = first_line.emplace(key, key_line); !inserted) {
      check.warnings.push_back({key_where, "duplicate key; the first one (line " +
                                               std::to_string(it->second) +
                                               ") is used, as AMBF does"});
      continue;
    }
    const bool is_known = std::find(known.begin(), known.end(), key) != known.end();
    if (is_known || (allow_mappings && entry.second.IsMap())) continue;
    const std::string message = "unknown key '" + key + "'" + suggestion(key, known);
    if (check.strict) throw LoadError(key_where, message);
    check.warnings.push_back({key_where, message + "; ignored"});
  }
}

}  // namespace common
