#include "placed_rings.hpp"

#include <fmt/format.h>

#include <regex>

namespace bench {

std::string PlacedRings::summary() const {
  return fmt::format("{}/{} rings; {}/{} episodes all six", rings, of, all_six, episodes);
}

std::optional<PlacedRings> placedRingsIn(const std::vector<std::string>& lines) {
  const std::regex placed(R"(placed (\d+)/(\d+) rings; (\d+)/(\d+) episodes all six)");
  std::optional<PlacedRings> found;
  std::smatch m;
  for (const std::string& line : lines) {
    if (std::regex_search(line, m, placed))
      found = PlacedRings{std::stoi(m[1]), std::stoi(m[2]), std::stoi(m[3]), std::stoi(m[4])};
  }
  return found;
}

}  // namespace bench
