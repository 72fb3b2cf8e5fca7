#include "twin/calibration_profile.hpp"
#include "twin/twin_platform.hpp"

namespace twin {

void CalibrationProfile::applyTo(TwinOptions& options) const {
  options.motors = mechanics;
  options.limits.servo_jr_delivered = servo_jr_delivered;
}

}  // namespace twin
