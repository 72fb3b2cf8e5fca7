// Compiled with no simulator on the include path (see tests/CMakeLists.txt): the platform
// interface and the cf recording format must not bring ambf_like or Bullet back in.

#include "bridge/raven_platform.hpp"
#include "controller/cf_recording.hpp"
