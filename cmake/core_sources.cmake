# The one list of core sources, and the one of the renderer's, shared by the native build
# (CMakeLists.txt) and the web build (cmake/web.cmake). Paths are relative to the
# repository root. Core has no GL.
set(DRAUGHT_CORE_SOURCES
  src/core/params/params.cpp
  src/core/params/json_input.cpp
  src/core/params/preset.cpp
  src/core/params/timeline.cpp
  src/core/params/object_params.cpp
  src/core/params/shipped_files.cpp
  src/core/scene/scene.cpp
  src/core/scene/camera.cpp
  src/core/scene/motion.cpp
  src/core/scene/frame.cpp
  src/core/droplets/field.cpp
  src/core/droplets/droplets.cpp
  src/core/droplets/trail.cpp
  src/core/condensation/condensation.cpp
  src/core/condensation/wall_grid.cpp
  src/core/pointcloud/cloud_object.cpp
  src/core/pointcloud/cloud_scene.cpp
  src/core/pointcloud/point_fields.cpp
  src/core/pointcloud/ply.cpp
  src/core/pointcloud/point_text.cpp
  src/core/pointcloud/cloud_files.cpp
  src/core/pointcloud/cloud_viewing.cpp
  src/core/pointcloud/blackbody.cpp
  src/core/pointcloud/glass_heat.cpp
  src/core/pointcloud/glow_light.cpp
  src/core/pointcloud/gob.cpp
  src/core/pointcloud/bvh.cpp
  src/core/pointcloud/field.cpp
  src/core/pointcloud/cloud_texels.cpp
  src/core/pointcloud/stream.cpp
  src/core/vessel/profile.cpp
  src/core/vessel/vessel.cpp
  src/core/vessel/fill_table.cpp
  src/core/vessel/decal.cpp
  src/core/vessel/decal_files.cpp
  src/core/vessel/view_thickness.cpp
  src/core/liquid/beverage.cpp
  src/core/liquid/haze.cpp
  src/core/liquid/slosh.cpp
  src/core/foam/foam.cpp
  src/core/foam/head_volume.cpp
  src/core/environment/reflection.cpp
  src/core/environment/paper_bounce.cpp
  src/core/environment/image_patches.cpp
  src/core/environment/media_light.cpp
  src/core/environment/studio.cpp
  src/core/environment/lights.cpp
  src/core/environment/sky_irradiance.cpp
  src/core/environment/backdrop.cpp
  src/core/environment/floor_light.cpp
  src/core/environment/backdrop_light.cpp
  src/core/environment/environment_map.cpp
  src/core/environment/environment_files.cpp
  src/core/environment/environment_sampling.cpp
  src/core/environment/environment_bake.cpp
  src/core/environment/screen.cpp
  src/core/environment/matcap.cpp
  src/core/quality/adaptive_quality.cpp
  src/core/bubbles/bubbles.cpp
  src/core/bubbles/bubble_view.cpp
  src/core/reference/intersect.cpp
  src/core/reference/decal_optics.cpp
  src/core/reference/optics.cpp
  src/core/reference/bodies.cpp
  src/core/reference/path_tracer.cpp
  src/core/sim/simulation.cpp
  src/core/sim/scene_simulation.cpp
  src/core/io/image.cpp
  src/core/io/hdr_image.cpp
  src/core/io/files.cpp
  src/core/io/temporaries.cpp
  src/core/io/process.cpp
  src/core/io/video_source.cpp
  src/core/output/cutout.cpp
  src/core/output/refine.cpp
  src/core/output/resolve.cpp
  src/core/text/echo.cpp
  src/core/text/suggest.cpp
  src/core/input/gesture.cpp
  src/core/input/fusion.cpp
  src/core/input/imu_driver.cpp
  src/core/input/device_motion.cpp
  src/core/input/combined.cpp
)
# The renderer's sources that both builds share (the native one adds the EGL context,
# src/gpu/context.cpp; the web one has WebGL2's).
set(DRAUGHT_GPU_SOURCES
  src/gpu/shader_source.cpp
  src/gpu/program.cpp
  src/gpu/scene_data.cpp
  src/gpu/decal_textures.cpp
  src/gpu/renderer.cpp
  src/gpu/screen_texture.cpp
  src/gpu/matcap_texture.cpp
  src/gpu/reflection_panoramas.cpp
  src/gpu/cloud_textures.cpp
  src/gpu/condensation_textures.cpp
)
# The headers nearly every core and renderer file includes, precompiled once per library in
# each build (native, web, sanitized): parsing glm and these standard headers took about
# 1.8 s of each file's compile, a third of a clean library build (docs/PERFORMANCE.md).
set(DRAUGHT_CORE_PRECOMPILED_HEADERS
  <algorithm> <array> <cmath> <cstdint> <filesystem> <functional> <memory> <optional>
  <sstream> <string> <vector>
  <glm/glm.hpp>)
function(draught_precompile_core_headers target)
  target_precompile_headers(${target} PRIVATE ${DRAUGHT_CORE_PRECOMPILED_HEADERS})
  # g++ 12 at -O3 warns of memcpy bounds inside std::string's operator+ and insert (GCC bug
  # 105329, false positives); from a precompiled header the library's lines lose the
  # system-header status that hides them otherwise. clang (web and sanitized builds) keeps
  # both warnings, and the sanitized unit suite checks bounds at run time.
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    target_compile_options(${target} PRIVATE -Wno-stringop-overflow -Wno-array-bounds)
  endif()
endfunction()
# The same lists as absolute paths, for builds whose source dir is not the root.
foreach(list DRAUGHT_CORE_SOURCES DRAUGHT_GPU_SOURCES)
  set(${list}_ABS "")
  foreach(src ${${list}})
    list(APPEND ${list}_ABS "${CMAKE_CURRENT_LIST_DIR}/../${src}")
  endforeach()
endforeach()
