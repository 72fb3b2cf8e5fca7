#pragma once
// Test helper: a cantilever of an elastic material, clamped at one end, sagging under its weight.

#include <vector>

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
  bool sleep = false;     ///< resting soft bodies sleep (the world's default settings)
};

/// How the beam ended.
struct CantileverSag {
  double tip_sag = 0;  ///< m, the mean drop of its tip face's nodes
  /// m, the farthest any node moved in each 50 ms of the run (the test of rest)
  std::vector<double> window_moves;
  /// s, when the windows' moves fell below `still` for good (the duration when they never did)
  double settledAfter(double still) const;
  bool finite = false;
  bool asleep = false;                 ///< at the end
  ambf_like::ElasticSolveStats solve;  ///< what its implicit steps took
};

/// Builds the beam, steps it for the spec's duration and measures it.
CantileverSag settleCantilever(const CantileverSpec& spec);

}  // namespace test_support
