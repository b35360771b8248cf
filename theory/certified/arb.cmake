# Arb (ball arithmetic, Debian libflint-arb-dev) and FLINT ship no CMake configuration: this finds them and
# defines the imported target affinterp::arb. Used by theory/certified/CMakeLists.txt and by the installed
# affinterpConfig.cmake (installed beside it).
macro(affinterp_find_arb)
  if(NOT TARGET affinterp::arb)
    find_path(AFFINTERP_ARB_INCLUDE_DIR arb.h)
    find_library(AFFINTERP_ARB_LIBRARY NAMES flint-arb arb)
    find_library(AFFINTERP_FLINT_LIBRARY NAMES flint)
    if(AFFINTERP_ARB_INCLUDE_DIR AND AFFINTERP_ARB_LIBRARY AND AFFINTERP_FLINT_LIBRARY)
      add_library(affinterp::arb UNKNOWN IMPORTED GLOBAL)
      set_target_properties(affinterp::arb PROPERTIES
        IMPORTED_LOCATION "${AFFINTERP_ARB_LIBRARY}"
        INTERFACE_INCLUDE_DIRECTORIES "${AFFINTERP_ARB_INCLUDE_DIR}"
        INTERFACE_LINK_LIBRARIES "${AFFINTERP_FLINT_LIBRARY}")
    endif()
  endif()
endmacro()
