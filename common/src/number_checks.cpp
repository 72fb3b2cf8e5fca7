#include "common/number_checks.hpp"

#include <cmath>
#include <cstdlib>
#include <functional>
#include <sstream>
#include <string>

namespace common {

namespace {

/// A bound as a person writes it (0.1, 1e-06, 20000).
std::string number(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

/// A check that the whole input reads as a finite number meeting `fits`, else "'input' is not
/// `wanted`".
CLI::Validator finiteNumber(std::function<bool(double)> fits, const std::string& wanted) {
  return CLI::Validator(
      [fits = std::move(fits), wanted](std::string& input) -> std::string {
        const char* begin = input.c_str();
        char* end = nullptr;
        const double value = std::strtod(begin, &end);
        const bool whole = end != begin && *end == '\0';
        return whole && std::isfinite(value) && fits(value) ? std::string()
                                                            : "'" + input + "' is not " + wanted;
      },
      wanted);
}

}  // namespace

CLI::Validator finiteWithin(double low, double high) {
  const bool from = std::isfinite(low), to = std::isfinite(high);
  const std::string wanted = from && to
                                 ? "a finite number in [" + number(low) + ", " + number(high) + "]"
                             : from ? "a finite number >= " + number(low)
                             : to   ? "a finite number <= " + number(high)
                                    : std::string("a finite number");
  return finiteNumber([low, high](double v) { return v >= low && v <= high; }, wanted);
}

CLI::Validator finiteAbove(double low) {
  return finiteNumber([low](double v) { return v > low; }, "a finite number > " + number(low));
}

}  // namespace common
