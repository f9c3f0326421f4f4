# The one shader-embedding function, used by the native and the web build:
# draught_embed_shaders(OUT_VAR) generates a C++ file that carries every shaders/**/*.glsl
# as a raw string (cmake/embed_shaders.cmake does the work at build time) and returns
# its path in OUT_VAR.
set(DRAUGHT_SHADER_ROOT "${CMAKE_CURRENT_LIST_DIR}/../shaders")
function(draught_embed_shaders out_var)
  file(GLOB_RECURSE shader_files CONFIGURE_DEPENDS "${DRAUGHT_SHADER_ROOT}/*.glsl")
  set(out "${CMAKE_BINARY_DIR}/generated/embedded_shaders.cpp")
  add_custom_command(
    OUTPUT "${out}"
    COMMAND ${CMAKE_COMMAND} -DOUT=${out} -DDIR=${DRAUGHT_SHADER_ROOT}
            -P "${CMAKE_CURRENT_FUNCTION_LIST_DIR}/embed_shaders.cmake"
    DEPENDS ${shader_files} "${CMAKE_CURRENT_FUNCTION_LIST_DIR}/embed_shaders.cmake"
    COMMENT "Embedding shaders")
  set(${out_var} "${out}" PARENT_SCOPE)
endfunction()
