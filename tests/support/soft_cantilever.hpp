#pragma once
// Test helper: a cantilever of an elastic material, clamped at one end, sagging under its weight.

#include "ambf_like/world.hpp"

namespace test_support {

/// A beam of `length` x `width` x `width` (m) along x, its face x = 0 clamped (fixed nodes),
/// `cells` cells through its thickness, of the material given, with Bullet's kDP damping.
struct CantileverSpec {
  double length = 0.04;
  double width = 0.005;
  int cells = 1;
  double youngs_modulus = 1e6;  ///< Pa
  double poisson = 0.45;
  double density = 1100;  ///< kg/m^3
  double damping = 0.02;  ///< kDP
  double step = 0.001;    ///< s
  int substeps = 1;
  double duration = 0.4;  ///< s simulated
};

/// How the beam ended.
struct CantileverSag {
  double tip_sag = 0;         ///< m, the mean drop of its tip face's nodes
  double last_step_move = 0;  ///< m, the farthest any node moved in the last step
  bool finite = false;
  ambf_like::ElasticSolveStats solve;  ///< what its implicit steps took
};

/// Builds the beam, steps it for the spec's duration and measures it.
CantileverSag settleCantilever(const CantileverSpec& spec);

}  // namespace test_support
