#pragma once
// How far from the origin a coordinate read from a file may lie.

namespace common {

/// Metres (or a mesh's own units before its scale): Bullet's bounds, contacts and inertia lose
/// every digit past it, and a pose beyond it turns a world non-finite within a step.
inline constexpr double kFarthestCoordinate = 1e5;

}  // namespace common
