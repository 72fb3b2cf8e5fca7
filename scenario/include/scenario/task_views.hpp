#pragma once
// The peg-transfer scene's named cameras: `overview` (both work areas: every ring on its post can
// be counted), `left-task` and `right-task` (one arm's three start and three target posts), and
// `grasper-left` / `grasper-right` (riding along with each arm's jaws).

#include <vector>

#include "ambf_like/world.hpp"
#include "scenario/peg_layout.hpp"
#include "viewer/view.hpp"

namespace scenario {

/// The views of a peg-transfer world (the shipped scene or one of its randomised variants).
/// Throws std::invalid_argument if the world has no Raven jaws to follow.
std::vector<viewer::View> pegTransferViews(const ambf_like::World& world,
                                           const PegLayout& layout = {});

/// The fixed camera on one arm's six posts (`left-task`, `right-task`), as designed: a
/// calibrated camera's pose and field of view.
viewer::Camera taskCamera(const PegLayout& layout, raven::Arm arm);

/// The view names, in the order pegTransferViews returns them.
std::vector<std::string> pegTransferViewNames();

}  // namespace scenario
