#include "inertia_check.hpp"

#include <sstream>

namespace ambf_like::detail {

std::optional<std::string> impossibleInertia(const Eigen::Vector3d& moments) {
  const double largest = moments.maxCoeff();
  const double others = moments.sum() - largest;
  if (largest - others <= kInertiaRoundingSlack * largest) return std::nullopt;
  std::ostringstream why;
  why << "principal moments " << moments.x() << ", " << moments.y() << ", " << moments.z()
      << " kg m^2 are no rigid body's: the largest exceeds the sum of the other two (every "
         "body's obey the triangle inequality)";
  return why.str();
}

}  // namespace ambf_like::detail
