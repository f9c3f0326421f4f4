# The web build: draught's core and renderer compiled with Emscripten into a static page
# (out/web/: index.html, page.js, style.css, draught.js, draught.wasm). WebGL2 through
# emscripten_webgl_create_context replaces the EGL context; everything else is the same
# source as the native build. Used by apps/web/CMakeLists.txt (scripts/build-web.sh):
#
#   emcmake cmake -S apps/web -B build-web && cmake --build build-web
#
# Needs only Debian packages: emscripten, nlohmann-json3-dev, libglm-dev, libstb-dev (their
# headers are linked into the build tree, since the Emscripten toolchain searches only its
# own sysroot). No ports, no downloads.
if(NOT EMSCRIPTEN)
  message(FATAL_ERROR "cmake/web.cmake: configure with emcmake (scripts/build-web.sh)")
endif()

get_filename_component(DRAUGHT_ROOT "${CMAKE_CURRENT_LIST_DIR}/.." ABSOLUTE)
set(DRAUGHT_WEB_OUT "${DRAUGHT_ROOT}/out/web" CACHE PATH "Where the page is written")

# ---- header-only dependencies from the host (Debian) ----
set(web_inc "${CMAKE_BINARY_DIR}/host-include")
file(MAKE_DIRECTORY "${web_inc}")
foreach(dep nlohmann/json.hpp glm/glm.hpp stb/stb_image.h)
  find_path(found_${dep} NAMES ${dep} PATHS /usr/include /usr/local/include NO_DEFAULT_PATH NO_CMAKE_FIND_ROOT_PATH)
  if(NOT found_${dep})
    message(FATAL_ERROR "web build: ${dep} not found (apt-get install nlohmann-json3-dev libglm-dev libstb-dev)")
  endif()
endforeach()
# Only these folders and files are exposed, never /usr/include itself (glibc's headers would
# shadow Emscripten's libc).
foreach(link nlohmann glm)
  if(NOT EXISTS "${web_inc}/${link}")
    file(CREATE_LINK "${found_nlohmann/json.hpp}/${link}" "${web_inc}/${link}" SYMBOLIC)
  endif()
endforeach()
foreach(h stb_image.h stb_image_write.h)
  if(NOT EXISTS "${web_inc}/${h}")
    file(CREATE_LINK "${found_stb/stb_image.h}/stb/${h}" "${web_inc}/${h}" SYMBOLIC)
  endif()
endforeach()

# ---- sources: all of core (it has no GL and no platform code), the renderer without
# the EGL context, the embedded shaders ----
include("${CMAKE_CURRENT_LIST_DIR}/core_sources.cmake")
set(web_core ${DRAUGHT_CORE_SOURCES_ABS})
# (Clang 14, Emscripten 3.1.6's compiler, cannot capture structured bindings in lambdas;
# src/ spells such captures out: [&, &key = key].)
set(web_gpu ${DRAUGHT_GPU_SOURCES_ABS})
include("${CMAKE_CURRENT_LIST_DIR}/shaders.cmake")
draught_embed_shaders(web_embedded)

set(web_flags -fexceptions)  # the core reports bad input by throwing
add_library(draught_web_core STATIC ${web_core} ${web_gpu} "${web_embedded}")
target_include_directories(draught_web_core PUBLIC "${DRAUGHT_ROOT}/src" "${DRAUGHT_GENERATED_INCLUDE_DIR}")
add_dependencies(draught_web_core draught_contract)  # generated/*.hpp before any compile
target_include_directories(draught_web_core SYSTEM PUBLIC "${web_inc}")
target_compile_options(draught_web_core PUBLIC ${web_flags})
draught_precompile_core_headers(draught_web_core)
target_compile_definitions(draught_web_core PRIVATE
  DRAUGHT_SOURCE_PRESET_DIR="/presets"
  DRAUGHT_VERSION="${PROJECT_VERSION}")

# ---- the page ----
file(GLOB web_presets CONFIGURE_DEPENDS "${DRAUGHT_ROOT}/presets/*/*.json")
add_executable(draught_web
  "${DRAUGHT_ROOT}/apps/web/main.cpp"
  "${DRAUGHT_ROOT}/apps/web/stb_impl.cpp")
target_link_libraries(draught_web PRIVATE draught_web_core)
set_target_properties(draught_web PROPERTIES
  OUTPUT_NAME draught SUFFIX ".js" RUNTIME_OUTPUT_DIRECTORY "${DRAUGHT_WEB_OUT}")
target_link_options(draught_web PRIVATE
  ${web_flags}
  -sMIN_WEBGL_VERSION=2 -sMAX_WEBGL_VERSION=2
  -sALLOW_MEMORY_GROWTH=1
  -sMODULARIZE=1 -sEXPORT_NAME=createDraught
  -sENVIRONMENT=web
  -sEXPORTED_RUNTIME_METHODS=UTF8ToString,GL,FS
  -sEXPORTED_FUNCTIONS=_main,_malloc,_free
  -sFILESYSTEM=1
  "--embed-file=${DRAUGHT_ROOT}/presets@/presets"
  "--exclude-file=*.md")
set_property(TARGET draught_web APPEND PROPERTY LINK_DEPENDS ${web_presets})

# Hand-written page files, copied next to the module.
add_custom_target(draught_web_page ALL
  COMMAND ${CMAKE_COMMAND} -E make_directory "${DRAUGHT_WEB_OUT}"
  COMMAND ${CMAKE_COMMAND} -E copy_if_different
          "${DRAUGHT_ROOT}/apps/web/index.html" "${DRAUGHT_ROOT}/apps/web/page.js"
          "${DRAUGHT_ROOT}/apps/web/style.css" "${DRAUGHT_WEB_OUT}/"
  DEPENDS "${DRAUGHT_ROOT}/apps/web/index.html" "${DRAUGHT_ROOT}/apps/web/page.js" "${DRAUGHT_ROOT}/apps/web/style.css"
  COMMENT "Copying the page")

# Debian's Emscripten runs its JS optimizer with node and finds acorn only through NODE_PATH.
if(EXISTS /usr/share/nodejs)
  set_property(TARGET draught_web PROPERTY RULE_LAUNCH_LINK "${CMAKE_COMMAND} -E env NODE_PATH=/usr/share/nodejs")
endif()
