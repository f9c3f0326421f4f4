# Unity builds (all three builds: native, web, sanitized): CMake compiles each target's
# sources in batches, one compiler run over several files, so the headers they share are
# parsed and their templates instantiated once a batch instead of once a file. The numbers
# are in docs/PERFORMANCE.md ("The build"). The price is that a file's file-local names
# (anonymous namespaces) share a batch with other files' names: a helper that two files
# need lives once in a header (core/math/, core/text/, core/io/bytes.hpp), and names that
# differ in meaning get different names. -DDRAUGHT_UNITY_BUILD=OFF builds file by file.
option(DRAUGHT_UNITY_BUILD "Compile each target's sources in batches (unity build)" ON)
if(DRAUGHT_UNITY_BUILD)
  set(CMAKE_UNITY_BUILD ON)
  if(NOT DEFINED CMAKE_UNITY_BUILD_BATCH_SIZE)
    set(CMAKE_UNITY_BUILD_BATCH_SIZE 8)
  endif()
endif()
# g++ takes a batch's later files for headers and warns that a class there holds a
# file-local type (-Wsubobject-linkage); in a .cpp file that is what file-local types are for.
if(DRAUGHT_UNITY_BUILD AND CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
  add_compile_options(-Wno-subobject-linkage)
endif()
