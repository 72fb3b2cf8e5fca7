#include "scenario/scene_variation.hpp"

#include <cmath>
#include <random>

#include "scenario/peg_layout.hpp"

namespace scenario {

SceneVariation SceneVariation::draw(std::uint64_t seed, const VariationRanges& r) {
  std::mt19937_64 random(seed);
  auto uniform = [&](double low, double high) {
    return std::uniform_real_distribution<double>(low, high)(random);
  };
  // A value of a range: anywhere in it, or at one of its ends.
  auto within = [&](const std::array<double, 2>& range) {
    if (!r.at_edges) return uniform(range[0], range[1]);
    return uniform(0.0, 1.0) < 0.5 ? range[0] : range[1];
  };
  SceneVariation v;
  v.seed = seed;
  v.nominal = false;
  for (std::size_t i = 0; i < 6; ++i) {
    v.ring_yaw[i] = uniform(0.0, 2.0 * M_PI);
    const double angle = uniform(0.0, 2.0 * M_PI),
                 radius = r.ring_offset * (r.at_edges ? 1.0 : std::sqrt(uniform(0, 1)));
    v.ring_offset[i] = radius * Eigen::Vector2d(std::cos(angle), std::sin(angle));
  }
  v.kDF = within(r.ring_kDF);
  v.ring_shore_a = within(r.ring_shore_a);
  v.board_friction = within(r.board_friction);
  return v;
}

double SceneVariation::ringYoungsModulus() const {
  return 1.0e6 * std::pow(10.0, 0.0235 * ring_shore_a - 0.6403);
}

void SceneVariation::apply(ambf_like::SceneSpec& scene) const {
  if (nominal) return;
  for (auto& model : scene.models) {
    for (auto& body : model.bodies) {
      if (body.name == "peg_board") body.surface.static_friction = board_friction;
    }
    for (auto& soft : model.soft_bodies) {
      const std::optional<std::size_t> ring = ringIndexOf(soft.name);
      if (!ring) continue;
      const std::size_t i = *ring;
      soft.location.translation().head<2>() += ring_offset[i];
      soft.location.linear() =
          Eigen::AngleAxisd(ring_yaw[i], Eigen::Vector3d::UnitZ()) * soft.location.linear();
      soft.config.kDF = kDF;
      if (soft.material) soft.material->youngs_modulus = ringYoungsModulus();
    }
  }
}

nlohmann::json SceneVariation::json() const {
  nlohmann::json j{{"seed", seed}, {"nominal", nominal}};
  if (nominal) return j;
  j["ring_yaw_rad"] = ring_yaw;
  for (const auto& o : ring_offset) j["ring_offset_m"].push_back({o.x(), o.y()});
  j["ring_kDF"] = kDF;
  j["ring_shore_a"] = ring_shore_a;
  j["ring_youngs_modulus_pa"] = ringYoungsModulus();
  j["board_friction"] = board_friction;
  return j;
}

}  // namespace scenario
