#pragma once
// The peg-transfer scene as it was before its rings had a material, for the loop-frequency
// comparison.

#include <filesystem>

namespace bench {

/// The shipped peg-transfer scene with its rings as they were before they were silicone:
/// position-based (links on every tetrahedron edge, shape matching 0.1, volume conservation 10, 2
/// g), with Coulomb contacts in 4 substeps of 2 iterations; gripped at 1.5 mm they held. Written
/// into `dir`; its launch file.
std::filesystem::path writePositionBasedPegScene(const std::filesystem::path& dir);

/// The squeeze (m) those rings were gripped with.
constexpr double kPositionBasedSqueeze = 0.0015;

}  // namespace bench
