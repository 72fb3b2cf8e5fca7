#include "scenario/scene_variation.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

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
  // Drawn after the scene's values, so a seed's scene is the same whatever the motors' range.
  v.actuation_sd = r.actuation_sd;
  for (auto& arm : v.actuation_draw) {
    for (auto& field : arm) {
      for (double& d : field) d = within({-1.0, 1.0});
    }
  }
  // The cameras' look last: it changes no physics.
  for (int i = 0; i < 3; ++i) v.camera_shift(i) = within({-r.camera_shift, r.camera_shift});
  v.camera_yaw = within({-r.camera_turn, r.camera_turn});
  v.camera_pitch = within({-r.camera_turn, r.camera_turn});
  v.camera_distance = within(r.camera_distance);
  v.light = within(r.light);
  for (int i = 0; i < 3; ++i) v.ring_tint(i) = within(r.tint);
  for (int i = 0; i < 3; ++i) v.body_tint(i) = within(r.tint);
  // The depth camera's errors after the look, so a seed's look is the same whatever they are.
  v.depth_noise = within(r.depth_noise);
  v.depth_scale = within(r.depth_scale);
  v.depth_baseline = within(r.depth_baseline);
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

twin::ArmsMechanics SceneVariation::mechanics(const twin::ArmsMechanics& fit,
                                              const twin::ArmsMechanics& sd) const {
  if (nominal) return fit;
  twin::ArmsMechanics out = fit;
  for (std::size_t a = 0; a < out.size(); ++a) {
    for (std::size_t k = 0; k < twin::MotorMechanics::kNames.size(); ++k) {
      const twin::MotorMechanics::ValueRange& range = twin::MotorMechanics::kRanges[k];
      for (int i = 0; i < raven::kJointCount; ++i) {
        const double f = fit[a].field(k)(i);
        double value = f + actuation_draw[a][k][static_cast<std::size_t>(i)] * actuation_sd *
                               sd[a].field(k)(i);
        value = std::clamp(value, range.low, range.high);
        // An open bound is never reached: a value is held at least halfway from it to the fit
        // (an inertia at least half the fitted one).
        if (range.open) value = std::max(value, 0.5 * (f + range.low));
        out[a].field(k)(i) = value;
      }
    }
  }
  return out;
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
  j["camera_shift_m"] = {camera_shift.x(), camera_shift.y(), camera_shift.z()};
  j["camera_yaw_rad"] = camera_yaw;
  j["camera_pitch_rad"] = camera_pitch;
  j["camera_distance"] = camera_distance;
  j["light"] = light;
  j["ring_tint"] = {ring_tint.x(), ring_tint.y(), ring_tint.z()};
  j["body_tint"] = {body_tint.x(), body_tint.y(), body_tint.z()};
  j["depth_noise_m"] = depth_noise;
  j["depth_scale"] = depth_scale;
  j["depth_baseline_m"] = depth_baseline;
  j["actuation_sd"] = actuation_sd;
  for (raven::Arm arm : raven::kArms) {
    for (std::size_t k = 0; k < twin::MotorMechanics::kNames.size(); ++k) {
      j["actuation_draw"][std::string(raven::armName(arm))]
       [std::string(twin::MotorMechanics::kNames[k])] = actuation_draw[raven::slot(arm)][k];
    }
  }
  return j;
}

}  // namespace scenario
