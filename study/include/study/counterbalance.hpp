#pragma once
// Counterbalancing the order of conditions across participants with a Williams design: a Latin
// square in which every condition comes once in each position and, over the design's rows,
// follows every other condition equally often (first-order carry-over balanced).

#include <vector>

namespace study {

/// The rows of a Williams design for `n` conditions: n rows when n is even, 2n when it is odd
/// (the square and its mirror). Each row is an order of 0..n-1.
std::vector<std::vector<int>> williamsDesign(int n);

/// The order of `n` conditions for the participant who is the `participant`-th (0-based) of the
/// study: row participant mod rows of the design.
std::vector<int> conditionOrder(int n, int participant);

}  // namespace study
