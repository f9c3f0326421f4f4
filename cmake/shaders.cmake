# The one shader-embedding function, used by the native and the web build:
# draught_embed_shaders(OUT_VAR) generates
#  - the C++/GLSL contract from src/interface/*.def (cmake/interface.cmake): headers
#    <build>/include/generated/<name>.hpp for C++ (core and gpu include them as
#    "generated/<name>.hpp") and their GLSL twins;
#  - one C++ file that carries every shaders/**/*.glsl and the generated GLSL
#    ("generated/<name>.glsl") as raw strings (cmake/embed_shaders.cmake);
# returns the C++ file in OUT_VAR, sets DRAUGHT_GENERATED_INCLUDE_DIR, and defines the
# target draught_contract that everything including a generated header depends on.
set(DRAUGHT_SHADER_ROOT "${CMAKE_CURRENT_LIST_DIR}/../shaders")
set(DRAUGHT_INTERFACE_ROOT "${CMAKE_CURRENT_LIST_DIR}/../src/interface")
function(draught_embed_shaders out_var)
  file(GLOB_RECURSE shader_files CONFIGURE_DEPENDS "${DRAUGHT_SHADER_ROOT}/*.glsl")
  file(GLOB defs CONFIGURE_DEPENDS "${DRAUGHT_INTERFACE_ROOT}/*.def")
  set(gen_dir "${CMAKE_BINARY_DIR}/include")
  set(generated "")
  foreach(def ${defs})
    get_filename_component(stem "${def}" NAME_WE)
    list(APPEND generated "${gen_dir}/generated/${stem}.hpp" "${gen_dir}/generated/${stem}.glsl")
  endforeach()
  set(out "${CMAKE_BINARY_DIR}/generated/embedded_shaders.cpp")
  set(here "${CMAKE_CURRENT_FUNCTION_LIST_DIR}")
  add_custom_command(
    OUTPUT "${out}"
    BYPRODUCTS ${generated}
    COMMAND ${CMAKE_COMMAND} -DOUT=${out} -DDIR=${DRAUGHT_SHADER_ROOT} -DDEFS_DIR=${DRAUGHT_INTERFACE_ROOT}
            -DGEN_DIR=${gen_dir} -P "${here}/embed_shaders.cmake"
    DEPENDS ${shader_files} ${defs} "${here}/embed_shaders.cmake" "${here}/interface.cmake"
    COMMENT "Generating the C++/GLSL contract and embedding shaders")
  add_custom_target(draught_contract DEPENDS "${out}")
  set(${out_var} "${out}" PARENT_SCOPE)
  set(DRAUGHT_GENERATED_INCLUDE_DIR "${gen_dir}" PARENT_SCOPE)
endfunction()
