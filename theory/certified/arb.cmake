# Arb (ball arithmetic, Debian libflint-arb-dev) and FLINT ship no CMake configuration: this finds them and
# defines the imported target affinterp::arb, with FLINT, MPFR and GMP (Arb's inline functions call GMP
# directly). Used by theory/certified/CMakeLists.txt and by the installed affinterpConfig.cmake (installed
# beside it).
macro(affinterp_find_arb)
  if(NOT TARGET affinterp::arb)
    find_path(AFFINTERP_ARB_INCLUDE_DIR arb.h)
    find_library(AFFINTERP_ARB_LIBRARY NAMES flint-arb arb)
    find_library(AFFINTERP_FLINT_LIBRARY NAMES flint)
    find_library(AFFINTERP_GMP_LIBRARY NAMES gmp)
    find_library(AFFINTERP_MPFR_LIBRARY NAMES mpfr)
    if(AFFINTERP_ARB_INCLUDE_DIR AND AFFINTERP_ARB_LIBRARY AND AFFINTERP_FLINT_LIBRARY AND AFFINTERP_GMP_LIBRARY
       AND AFFINTERP_MPFR_LIBRARY)
      add_library(affinterp::arb UNKNOWN IMPORTED GLOBAL)
      set_target_properties(affinterp::arb PROPERTIES
        IMPORTED_LOCATION "${AFFINTERP_ARB_LIBRARY}"
        INTERFACE_INCLUDE_DIRECTORIES "${AFFINTERP_ARB_INCLUDE_DIR}"
        INTERFACE_LINK_LIBRARIES "${AFFINTERP_FLINT_LIBRARY};${AFFINTERP_MPFR_LIBRARY};${AFFINTERP_GMP_LIBRARY}")
    endif()
  endif()
endmacro()
