#pragma once
// Where in a session one motor's twin-vs-robot difference sits: the rows cut into windows, each
// window's share of the summed |twin - physical| over the trials, and its mean.

#include <cstddef>
#include <vector>

#include "analysis/actuator_signals.hpp"

namespace analysis {

/// One window of rows [first_row, last_row] and what its rows hold of one motor's difference.
struct ErrorWindow {
  std::size_t first_row = 0, last_row = 0;
  double start = 0.0, end = 0.0;  ///< s, the first physical trial's times at those rows
  double share = 0.0;             ///< of the sum of |twin - physical| over every row and trial
  double mean = 0.0;              ///< mean |twin - physical| over the window's rows and trials
};

/// One motor (an arm's joint index) of one signal, in windows of `rows_per_window` rows, rows
/// paired by index as the score pairs them, over the rows every trace has. One twin trace per
/// physical trace, or one for all. Throws std::invalid_argument for no trial, a twin trace count
/// that fits neither, a joint out of range or windows of no rows.
std::vector<ErrorWindow> errorWindows(const std::vector<ActuatorTrace>& twin,
                                      const std::vector<ActuatorTrace>& physical,
                                      ActuatorSignal signal, raven::Arm arm, int joint,
                                      std::size_t rows_per_window);

}  // namespace analysis
