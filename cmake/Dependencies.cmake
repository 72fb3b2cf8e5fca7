# Every third-party dependency, found once, from Debian 12's packages (see scripts/install-deps.sh).

find_package(PkgConfig REQUIRED)
find_package(Eigen3 3.4 REQUIRED NO_MODULE)
find_package(yaml-cpp REQUIRED)
find_package(spdlog REQUIRED)
find_package(CLI11 REQUIRED)
find_package(nlohmann_json 3 REQUIRED)
find_package(Threads REQUIRED)

# The simulator's own: Bullet, assimp, urdfdom and TinyXML (not needed by a robot-side build).
if(RAVEN_SIMULATOR)
  # Debian ships float and double Bullet side by side; only the float64 module defines
  # BT_USE_DOUBLE_PRECISION. Plain find_package(Bullet) would silently pick the float build.
  pkg_check_modules(BULLET REQUIRED IMPORTED_TARGET bullet-float64)
  if(NOT BULLET_CFLAGS MATCHES "BT_USE_DOUBLE_PRECISION")
    message(FATAL_ERROR "bullet-float64 does not define BT_USE_DOUBLE_PRECISION: refusing to mix precisions")
  endif()
  find_package(assimp REQUIRED)
  find_package(urdfdom REQUIRED)
  # TinyXML, the parser under urdfdom (its -dev package comes with urdfdom's): the URDF reader
  # parses with it too, for the lines urdfdom does not report.
  pkg_check_modules(TINYXML REQUIRED IMPORTED_TARGET tinyxml)
endif()
