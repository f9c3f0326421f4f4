# The desktop viewer: an SDL2 window with an OpenGL ES 3.0 context, the same renderer and
# shaders as the headless CLI, and a Dear ImGui panel generated from the parameter table.
# Included by the root CMakeLists.txt after draught_gpu and draught_sdl_input exist.

# Dear ImGui from Debian's libimgui-dev: the core is a static library; the platform and
# renderer backends ship as sources, which we compile here so the OpenGL one targets GLES 3
# (the prebuilt copies inside libimgui.a use a desktop GL loader).
pkg_check_modules(IMGUI QUIET IMPORTED_TARGET imgui)
find_path(DRAUGHT_IMGUI_BACKEND_DIR imgui_impl_opengl3.cpp
  PATHS /usr/share/doc/libimgui-dev/examples/backends NO_DEFAULT_PATH)
find_path(DRAUGHT_IMGUI_BACKEND_INCLUDE_DIR imgui_impl_sdl.h PATH_SUFFIXES imgui/backends)
if(NOT IMGUI_FOUND OR NOT DRAUGHT_IMGUI_BACKEND_DIR OR NOT DRAUGHT_IMGUI_BACKEND_INCLUDE_DIR)
  message(FATAL_ERROR
    "draught-viewer needs Dear ImGui: install the Debian package libimgui-dev "
    "(scripts/deps.sh does), which provides imgui.pc, libimgui.a and the backend sources in "
    "/usr/share/doc/libimgui-dev/examples/backends/")
endif()

set(DRAUGHT_IMGUI_BACKENDS
  ${DRAUGHT_IMGUI_BACKEND_DIR}/imgui_impl_sdl.cpp
  ${DRAUGHT_IMGUI_BACKEND_DIR}/imgui_impl_opengl3.cpp)
# Third-party code: not held to our warning flags.
set_source_files_properties(${DRAUGHT_IMGUI_BACKENDS} PROPERTIES COMPILE_OPTIONS "-w")

# The editor (parameters, undo history, presets), the layout and the droplets pointer have no
# GL or ImGui, so tests link them alone.
add_library(draught_viewer_editor STATIC apps/viewer/editor.cpp apps/viewer/layout.cpp apps/viewer/pointer.cpp)
target_include_directories(draught_viewer_editor PUBLIC apps/viewer)
target_link_libraries(draught_viewer_editor PUBLIC draught_core)

# Backends compiled into the executable itself, so their symbols win over the copies in
# libimgui.a whatever the link order.
add_executable(draught-viewer
  apps/viewer/main.cpp
  apps/viewer/app.cpp
  apps/viewer/events.cpp
  apps/viewer/window.cpp
  apps/viewer/params_panel.cpp
  apps/viewer/preset_panel.cpp
  ${DRAUGHT_IMGUI_BACKENDS})
target_include_directories(draught-viewer PRIVATE ${DRAUGHT_IMGUI_BACKEND_INCLUDE_DIR})
target_compile_definitions(draught-viewer PRIVATE IMGUI_IMPL_OPENGL_ES3 DRAUGHT_VERSION="${PROJECT_VERSION}")
target_link_libraries(draught-viewer PRIVATE
  draught_viewer_editor draught_gpu draught_sdl_input PkgConfig::IMGUI PkgConfig::SDL2 CLI11::CLI11)

if(DRAUGHT_TESTS)
  # tests/CMakeLists.txt found GTest in its own directory scope; the targets are not visible here.
  find_package(GTest REQUIRED)
  include(GoogleTest)

  # The editor without a window: undo, presets, load and save errors, selection, layout, the
  # mouse as the droplets pointer.
  add_executable(viewer_editor_tests tests/viewer/test_editor.cpp tests/viewer/test_selection.cpp
    tests/viewer/test_layout.cpp tests/viewer/test_pointer.cpp)
  target_link_libraries(viewer_editor_tests PRIVATE draught_viewer_editor GTest::gtest_main)
  gtest_discover_tests(viewer_editor_tests DISCOVERY_TIMEOUT 30)

  # Key events fed frame by frame to the real ImGui and its SDL backend (SDL's dummy video
  # driver: no display): a key pressed and released within one frame still acts.
  add_executable(viewer_events_tests tests/viewer/test_events.cpp apps/viewer/events.cpp
    ${DRAUGHT_IMGUI_BACKEND_DIR}/imgui_impl_sdl.cpp)
  target_include_directories(viewer_events_tests PRIVATE apps/viewer ${DRAUGHT_IMGUI_BACKEND_INCLUDE_DIR})
  target_link_libraries(viewer_events_tests PRIVATE PkgConfig::IMGUI PkgConfig::SDL2 GTest::gtest_main)
  gtest_discover_tests(viewer_events_tests DISCOVERY_TIMEOUT 30 PROPERTIES ENVIRONMENT "SDL_VIDEODRIVER=dummy")

  # The viewer in a real (virtual) X server: a screenshot must show the glass and the panel.
  add_executable(viewer_check_screenshot tests/viewer/check_screenshot.cpp)
  target_link_libraries(viewer_check_screenshot PRIVATE draught_core)
  find_program(DRAUGHT_XVFB_RUN xvfb-run)
  if(DRAUGHT_XVFB_RUN)
    add_test(NAME viewer_screenshot
      COMMAND bash ${CMAKE_SOURCE_DIR}/tests/viewer/screenshot_test.sh ${DRAUGHT_XVFB_RUN}
              $<TARGET_FILE:draught-viewer> $<TARGET_FILE:viewer_check_screenshot>
              ${CMAKE_BINARY_DIR}/viewer-test)
  else()
    # Not skipped: a missing package is a broken setup, not a passing test.
    add_test(NAME viewer_screenshot
      COMMAND bash -c "echo 'viewer_screenshot: xvfb-run not found: install the Debian packages xvfb and xauth (scripts/deps.sh does), then re-run cmake' >&2; exit 1")
  endif()
  set_tests_properties(viewer_screenshot PROPERTIES
    # (GALLIVM_PERF: llvmpipe's JIT without LLVM's passes, as the GPU tests; see tests/CMakeLists.txt.)
    ENVIRONMENT "LIBGL_ALWAYS_SOFTWARE=1;SDL_VIDEODRIVER=x11;GALLIVM_PERF=nopt"
    TIMEOUT 180)
endif()
