# With AFFINTERP_NATIVE the project's libraries are compiled for the building machine's CPU (-march=native):
# the experiments and the benchmarks measure that code. A library installed or handed to another machine
# must not be: on a CPU without, say, AVX-512 it would die on an illegal instruction. So the package gets
# `<target>_portable`, a copy of <target> built from the same sources with the same settings but without
# -march=native (the compiler's baseline, x86-64 on amd64), under the same archive and export names.
# checks/ copies the floating-point tests of theory/ the same way: they run against these libraries too.
# Call it in theory/ (where the per-source COMPILE_OPTIONS of affinterp_theory live), the copies of the
# libraries a target links made first: a link to a library that has a copy (by its name or an alias) goes
# to the copy.
function(affinterp_add_portable_copy target)
  set(copy ${target}_portable)
  get_target_property(source_dir ${target} SOURCE_DIR)
  get_target_property(sources ${target} SOURCES)
  set(absolute_sources "")
  foreach(source IN LISTS sources)
    cmake_path(ABSOLUTE_PATH source BASE_DIRECTORY ${source_dir})
    list(APPEND absolute_sources ${source})
  endforeach()
  get_target_property(type ${target} TYPE)
  if(type STREQUAL "EXECUTABLE")
    add_executable(${copy} ${absolute_sources})
    get_target_property(output_directory ${target} RUNTIME_OUTPUT_DIRECTORY)
    if(output_directory)
      set_target_properties(${copy} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${output_directory})
    endif()
  elseif(type STREQUAL "OBJECT_LIBRARY")
    add_library(${copy} OBJECT ${absolute_sources})
  else()
    add_library(${copy} STATIC ${absolute_sources})
    get_target_property(output_name ${target} NAME)
    set_target_properties(${copy} PROPERTIES OUTPUT_NAME ${output_name}
                          ARCHIVE_OUTPUT_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/portable)
  endif()
  # Everything else is the original's, set here rather than inherited from this folder.
  foreach(property COMPILE_OPTIONS COMPILE_DEFINITIONS COMPILE_FEATURES INCLUDE_DIRECTORIES LINK_LIBRARIES PRECOMPILE_HEADERS
                   INTERFACE_COMPILE_OPTIONS INTERFACE_COMPILE_DEFINITIONS INTERFACE_COMPILE_FEATURES
                   INTERFACE_INCLUDE_DIRECTORIES INTERFACE_LINK_LIBRARIES EXPORT_NAME PRECOMPILE_HEADERS_REUSE_FROM UNITY_BUILD)
    get_target_property(value ${target} ${property})
    if(NOT value)
      if(property STREQUAL "PRECOMPILE_HEADERS_REUSE_FROM")
        continue()  # set, even to nothing, it would be a reuse of no target
      endif()
      set(value "")
    endif()
    list(REMOVE_ITEM value -march=native)
    foreach(dependency IN LISTS value)
      affinterp_portable_name(${dependency} dependency_copy)
      if(dependency_copy)
        list(TRANSFORM value REPLACE "^${dependency}$" ${dependency_copy})
      endif()
    endforeach()
    set_property(TARGET ${copy} PROPERTY ${property} ${value})
  endforeach()
endfunction()

# affinterp_portable_name(NAME OUT): OUT is the portable copy of the target NAME names (itself or through an
# alias), or empty when it has none.
function(affinterp_portable_name name out)
  set(${out} "" PARENT_SCOPE)
  if(NOT TARGET ${name})
    return()
  endif()
  get_target_property(aliased ${name} ALIASED_TARGET)
  if(aliased)
    set(name ${aliased})
  endif()
  if(TARGET ${name}_portable)
    set(${out} ${name}_portable PARENT_SCOPE)
  endif()
endfunction()
