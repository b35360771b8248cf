# With AFFINTERP_NATIVE the project's libraries are compiled for the building machine's CPU (-march=native):
# the experiments and the benchmarks measure that code. A library installed or handed to another machine
# must not be: on a CPU without, say, AVX-512 it would die on an illegal instruction. So the package gets
# `<target>_portable`, a copy of <target> built from the same sources with the same settings but without
# -march=native (the compiler's baseline, x86-64 on amd64), under the same archive and export names.
# Call it in theory/ (where the per-source COMPILE_OPTIONS of affinterp_theory live), the copies of the
# libraries a target links made first: a link to a library that has a copy goes to the copy.
function(affinterp_add_portable_copy target)
  set(copy ${target}_portable)
  get_target_property(source_dir ${target} SOURCE_DIR)
  get_target_property(sources ${target} SOURCES)
  set(absolute_sources "")
  foreach(source IN LISTS sources)
    cmake_path(ABSOLUTE_PATH source BASE_DIRECTORY ${source_dir})
    list(APPEND absolute_sources ${source})
  endforeach()
  add_library(${copy} STATIC ${absolute_sources})
  get_target_property(output_name ${target} NAME)
  set_target_properties(${copy} PROPERTIES OUTPUT_NAME ${output_name}
                        ARCHIVE_OUTPUT_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/portable)
  # Everything else is the original's, set here rather than inherited from this folder.
  foreach(property COMPILE_OPTIONS COMPILE_DEFINITIONS COMPILE_FEATURES INCLUDE_DIRECTORIES LINK_LIBRARIES PRECOMPILE_HEADERS
                   INTERFACE_COMPILE_OPTIONS INTERFACE_COMPILE_DEFINITIONS INTERFACE_COMPILE_FEATURES
                   INTERFACE_INCLUDE_DIRECTORIES INTERFACE_LINK_LIBRARIES EXPORT_NAME)
    get_target_property(value ${target} ${property})
    if(NOT value)
      set(value "")
    endif()
    list(REMOVE_ITEM value -march=native)
    foreach(dependency IN LISTS value)
      if(TARGET ${dependency}_portable)
        list(TRANSFORM value REPLACE "^${dependency}$" ${dependency}_portable)
      endif()
    endforeach()
    set_property(TARGET ${copy} PROPERTY ${property} ${value})
  endforeach()
endfunction()
