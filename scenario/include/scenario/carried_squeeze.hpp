#pragma once
// Each jaw's squeeze on a ring while it is carried, in newtons, as the run's table reports it.

#include <array>
#include <map>
#include <string>
#include <vector>

#include "twin/grasp_forces.hpp"

namespace scenario {

/// Collects, per ring, each jaw's normal force (measured_cf) at every iteration its arm carries
/// it, and answers with the median per jaw.
class CarriedSqueeze {
 public:
  /// One iteration of `ring` carried by a grasper whose forces are `forces`.
  void record(const std::string& ring, const bridge::GrasperForces& forces);
  /// The median normal force (N) of each jaw on `ring` while carried; zeros if it never was.
  std::array<double, 2> median(const std::string& ring) const;

 private:
  std::map<std::string, std::array<std::vector<double>, 2>> samples_;
};

}  // namespace scenario
