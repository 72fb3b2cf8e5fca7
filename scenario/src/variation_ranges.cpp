// Reads the ranges a randomised scene is drawn from (scene_variation.hpp).

#include <fmt/format.h>

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "common/load_error.hpp"
#include "common/yaml_view.hpp"
#include "raven/design/peg_scene_design.hpp"
#include "scenario/scene_variation.hpp"

namespace scenario {

namespace {

constexpr std::array<std::string_view, 14> kKeys{
    "ring_offset",  "ring_kDF",    "ring_shore_a",    "board_friction", "actuation_sd",
    "camera_shift", "camera_turn", "camera_distance", "light",          "tint",
    "depth_noise",  "depth_scale", "depth_baseline",  "at_edges"};

/// The [low, high] at `key`, within [least, most], if the key is there.
void readRange(const common::YamlView& node, const char* key, double least, double most,
               std::array<double, 2>& range) {
  const auto found = node.find(key);
  if (!found) return;
  const std::vector<double> v = found->asDoubleList(2);
  if (v[0] > v[1] || v[0] < least || v[1] > most) {
    throw common::LoadError(
        found->where(), fmt::format("[{}, {}] is not a range within [{}, {}] (low <= high)", v[0],
                                    v[1], least, most));
  }
  range = {v[0], v[1]};
}

/// The value at `key`, which must be >= 0, if the key is there.
void readNonNegative(const common::YamlView& node, const char* key, double& value) {
  const auto found = node.find(key);
  if (!found) return;
  value = found->asDouble();
  if (!(value >= 0.0)) throw common::LoadError(found->where(), "must be >= 0");
}

/// The ring_offset, if given: a ring starts around its post, so at most the gap between the
/// ring's hole and the post (3.5 mm; farther, its wall would start inside the post, and 1e300
/// made the world's state non-finite).
void readRingOffset(const common::YamlView& node, double& value) {
  const raven::design::PegSceneDesign design;
  const double most = design.ring_major_radius - design.ring_minor_radius - design.post_radius;
  readNonNegative(node, "ring_offset", value);
  if (value > most) {
    throw common::LoadError(
        node.find("ring_offset")->where(),
        fmt::format("{} m would start a ring off its post: at most {} m (its hole's radius less "
                    "the post's)",
                    value, most));
  }
}

}  // namespace

VariationRanges readVariationRanges(const std::filesystem::path& file) {
  const common::YamlView root = common::YamlView::parseFile(file);
  if (!root.isMap()) throw common::LoadError(root.where(), "variation ranges: a mapping of ranges");
  std::vector<common::LoadIssue> duplicates;
  root.checkKeys(kKeys, {true, duplicates});
  if (!duplicates.empty()) throw common::LoadError(duplicates);
  VariationRanges r;
  readRingOffset(root, r.ring_offset);
  readNonNegative(root, "actuation_sd", r.actuation_sd);
  readNonNegative(root, "camera_shift", r.camera_shift);
  readNonNegative(root, "camera_turn", r.camera_turn);
  constexpr double kUnbounded = 1e9;
  readRange(root, "ring_kDF", 0.0, 1.0, r.ring_kDF);
  readRange(root, "ring_shore_a", 0.0, 100.0, r.ring_shore_a);
  readRange(root, "board_friction", 0.0, kUnbounded, r.board_friction);
  constexpr double kLeastFactor = 1e-3;  // a factor of 0 would leave nothing to see
  readRange(root, "camera_distance", kLeastFactor, kUnbounded, r.camera_distance);
  readRange(root, "light", kLeastFactor, kUnbounded, r.light);
  readRange(root, "tint", kLeastFactor, kUnbounded, r.tint);
  readRange(root, "depth_noise", 0.0, kUnbounded, r.depth_noise);
  readRange(root, "depth_scale", kLeastFactor, kUnbounded, r.depth_scale);
  readRange(root, "depth_baseline", 0.0, kUnbounded, r.depth_baseline);
  if (const auto edges = root.find("at_edges")) r.at_edges = edges->asBool();
  return r;
}

}  // namespace scenario
