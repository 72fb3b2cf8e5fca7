#include "study/counterbalance.hpp"

#include <algorithm>
#include <stdexcept>

namespace study {

std::vector<std::vector<int>> williamsDesign(int n) {
  if (n < 1) throw std::invalid_argument("a design needs at least one condition");
  // First row 0, 1, n-1, 2, n-2, ...; each further row adds one (mod n).
  std::vector<int> first{0};
  for (int k = 1, low = 1, high = n - 1; k < n; ++k) first.push_back(k % 2 == 1 ? low++ : high--);
  std::vector<std::vector<int>> rows;
  for (int r = 0; r < n; ++r) {
    std::vector<int> row;
    for (int c : first) row.push_back((c + r) % n);
    rows.push_back(row);
  }
  if (n % 2 == 1) {
    for (int r = 0; r < n; ++r) {
      rows.push_back(rows[static_cast<std::size_t>(r)]);
      std::reverse(rows.back().begin(), rows.back().end());
    }
  }
  return rows;
}

std::vector<int> conditionOrder(int n, int participant) {
  if (participant < 0) throw std::invalid_argument("a participant's position is 0 or more");
  const auto rows = williamsDesign(n);
  return rows[static_cast<std::size_t>(participant) % rows.size()];
}

}  // namespace study
