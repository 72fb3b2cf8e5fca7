#pragma once
// The paper's recording formats (../shared/reference/dual-platform-controller.md): `rs` robot
// state (240 named columns after an unnamed index column) and `ci` controller inputs (14).

#include <array>
#include <string>
#include <vector>

#include "bridge/raven_state.hpp"

namespace recording {

/// The 240 rs column names, in file order: time, jpos0..15, runlevel, ..., jac_f0..11.
const std::vector<std::string>& rsColumnNames();

/// One rs row from a raven_state sample: time relative to `t0`, jpos and jvel converted from
/// degrees to radians (so the insertion is in metres), every other field as the robot sends it.
std::vector<double> rsRow(const bridge::RavenStateSnapshot& state, double t0);

/// The paper's recorder writes every field but time as float("%.6f"); printed as Python prints
/// a float ("0.0", "0.522171", "-78246.0"); NaN as an empty field.
std::string formatRsValue(double value, bool round_to_micro = true);

}  // namespace recording
