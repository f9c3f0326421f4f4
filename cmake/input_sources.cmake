# Input drivers: included by the root CMakeLists.txt right after draught_core is defined.
target_sources(draught_core PRIVATE
  src/core/input/gesture.cpp
  src/core/input/fusion.cpp
  src/core/input/imu_driver.cpp
  src/core/input/device_motion.cpp
  src/core/input/combined.cpp)

# The SDL2 gamepad adapter: only what links it (the desktop viewer, its tests) needs SDL2.
pkg_check_modules(SDL2 REQUIRED IMPORTED_TARGET sdl2)
add_library(draught_sdl_input STATIC src/platform/sdl_gamepad.cpp)
target_link_libraries(draught_sdl_input PUBLIC draught_core PkgConfig::SDL2)
