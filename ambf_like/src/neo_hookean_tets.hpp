#pragma once
// A soft body's tetrahedra as a Neo-Hookean solid, solved as compliant constraints (XPBD).

#include <Eigen/Core>
#include <array>
#include <vector>

#include "ambf_like/soft_body_spec.hpp"

class btSoftBody;

namespace ambf_like::detail {

/// The stable Neo-Hookean energy per unit rest volume,
///   psi(F) = mu/2 tr(F^T F) + lambda/2 (det F - gamma)^2,  gamma = 1 + mu / lambda,
/// (Smith et al. 2018, without its log term) written as two constraints per tetrahedron, the
/// deviatoric C_D = |F| with compliance 1 / (mu V) and the hydrostatic C_H = det F - gamma with
/// compliance 1 / (lambda V) (Macklin and Mueller 2021). lambda is Lame's first parameter plus
/// mu, so that small strains answer exactly as linear elasticity with the material's E and nu.
///
/// Solved by XPBD (Macklin, Mueller and Chentanez 2016) with each constraint's multiplier warm
/// started from the force it carried in the previous substep. Without the warm start a few
/// Gauss-Seidel iterations leave a stiff solid softer than its material, by an amount that
/// depends on the step and the iteration count; with it, a body at rest is a fixed point exactly
/// where its elastic forces balance the loads on it, whatever the step, substeps and iterations.
/// The price is a stability bound on the substep, stableSubstep(), which the solver respects.
class NeoHookeanTets {
 public:
  /// The tetrahedra of `body` (rest shape: the nodes where they are now).
  NeoHookeanTets(const btSoftBody& body, const SoftMaterial& material);

  /// The longest substep this solid's stiffest element and lightest node stay stable at.
  double stableSubstep() const { return stable_substep_; }

  /// Starts a substep of `h`: each constraint begins with the force it carried last, applied.
  void warmStart(btSoftBody& body, double h);
  /// One Gauss-Seidel pass over every constraint, for a substep of `h`.
  void iterate(btSoftBody& body, double h);
  /// Ends a substep of `h`: keeps each constraint's force for the next one's warm start.
  void finishSubstep(double h);

 private:
  /// One tetrahedron: its nodes, inverse rest edge matrix, rest volume, and the multipliers
  /// (deviatoric, hydrostatic) of the substep being solved.
  struct Tetrahedron {
    std::array<int, 4> node;
    Eigen::Matrix3d rest_inverse;
    double volume = 0.0;
    std::array<double, 2> multiplier{0.0, 0.0};
    std::array<double, 2> force{0.0, 0.0};  ///< multiplier / h^2 of the last substep
  };

  /// One XPBD update of one constraint of `tet` (0: deviatoric, 1: hydrostatic).
  void solve(btSoftBody& body, Tetrahedron& tet, int which, double h) const;

  double mu_;
  double lambda_;
  double gamma_;
  double stable_substep_ = 0.0;
  double damping_time_ = 0.0;  ///< Rayleigh stiffness-proportional damping (s)
  std::vector<Tetrahedron> tets_;
  std::vector<Eigen::Vector3d> shift_;  ///< scratch: each node's warm-start displacement
};

}  // namespace ambf_like::detail
