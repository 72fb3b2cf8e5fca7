#include "scenario/scene_variation.hpp"

#include <cmath>
#include <random>

namespace scenario {

SceneVariation SceneVariation::draw(std::uint64_t seed, const VariationRanges& r) {
  std::mt19937_64 random(seed);
  auto uniform = [&](double low, double high) {
    return std::uniform_real_distribution<double>(low, high)(random);
  };
  SceneVariation v;
  v.seed = seed;
  v.nominal = false;
  for (std::size_t i = 0; i < 6; ++i) {
    v.peg_yaw[i] = uniform(0.0, 2.0 * M_PI);
    const double angle = uniform(0.0, 2.0 * M_PI), radius = r.peg_offset * std::sqrt(uniform(0, 1));
    v.peg_offset[i] = radius * Eigen::Vector2d(std::cos(angle), std::sin(angle));
  }
  v.kDF = uniform(r.peg_kDF[0], r.peg_kDF[1]);
  v.peg_shore_a = uniform(r.peg_shore_a[0], r.peg_shore_a[1]);
  v.board_friction = uniform(r.board_friction[0], r.board_friction[1]);
  return v;
}

double SceneVariation::pegYoungsModulus() const {
  return 1.0e6 * std::pow(10.0, 0.0235 * peg_shore_a - 0.6403);
}

void SceneVariation::apply(ambf_like::SceneSpec& scene) const {
  if (nominal) return;
  for (auto& model : scene.models) {
    for (auto& body : model.bodies) {
      if (body.name == "peg_board") body.surface.static_friction = board_friction;
    }
    for (auto& soft : model.soft_bodies) {
      if (soft.name.rfind("peg", 0) != 0) continue;
      const auto i = static_cast<std::size_t>(std::stoi(soft.name.substr(3)) - 1);
      if (i >= 6) continue;
      soft.location.translation().head<2>() += peg_offset[i];
      soft.location.linear() =
          Eigen::AngleAxisd(peg_yaw[i], Eigen::Vector3d::UnitZ()) * soft.location.linear();
      soft.config.kDF = kDF;
      if (soft.material) soft.material->youngs_modulus = pegYoungsModulus();
    }
  }
}

nlohmann::json SceneVariation::json() const {
  nlohmann::json j{{"seed", seed}, {"nominal", nominal}};
  if (nominal) return j;
  j["peg_yaw_rad"] = peg_yaw;
  for (const auto& o : peg_offset) j["peg_offset_m"].push_back({o.x(), o.y()});
  j["peg_kDF"] = kDF;
  j["peg_shore_a"] = peg_shore_a;
  j["peg_youngs_modulus_pa"] = pegYoungsModulus();
  j["board_friction"] = board_friction;
  return j;
}

}  // namespace scenario
