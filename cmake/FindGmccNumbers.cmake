# FindGmccNumbers: the exact and multiple-precision number libraries gmcc's public headers use.
#   GMP (mpz/mpq), gmpxx (mpq_class, gmcc::Rational), MPFR, MPFI (certified intervals).
# Defines imported targets gmcc_deps::gmpxx, gmcc_deps::gmp, gmcc_deps::mpfr, gmcc_deps::mpfi.
include(FindPackageHandleStandardArgs)
find_path(GmccNumbers_GMP_INCLUDE gmp.h)
find_path(GmccNumbers_MPFI_INCLUDE mpfi.h)
find_library(GmccNumbers_GMP_LIB gmp)
find_library(GmccNumbers_GMPXX_LIB gmpxx)
find_library(GmccNumbers_MPFR_LIB mpfr)
find_library(GmccNumbers_MPFI_LIB mpfi)
find_package_handle_standard_args(GmccNumbers REQUIRED_VARS
  GmccNumbers_GMP_INCLUDE GmccNumbers_MPFI_INCLUDE GmccNumbers_GMP_LIB GmccNumbers_GMPXX_LIB
  GmccNumbers_MPFR_LIB GmccNumbers_MPFI_LIB)
if(GmccNumbers_FOUND AND NOT TARGET gmcc_deps::gmp)
  add_library(gmcc_deps::gmp UNKNOWN IMPORTED)
  set_target_properties(gmcc_deps::gmp PROPERTIES IMPORTED_LOCATION "${GmccNumbers_GMP_LIB}"
    INTERFACE_INCLUDE_DIRECTORIES "${GmccNumbers_GMP_INCLUDE}")
  add_library(gmcc_deps::gmpxx UNKNOWN IMPORTED)
  set_target_properties(gmcc_deps::gmpxx PROPERTIES IMPORTED_LOCATION "${GmccNumbers_GMPXX_LIB}"
    INTERFACE_LINK_LIBRARIES gmcc_deps::gmp)
  add_library(gmcc_deps::mpfr UNKNOWN IMPORTED)
  set_target_properties(gmcc_deps::mpfr PROPERTIES IMPORTED_LOCATION "${GmccNumbers_MPFR_LIB}"
    INTERFACE_LINK_LIBRARIES gmcc_deps::gmp)
  add_library(gmcc_deps::mpfi UNKNOWN IMPORTED)
  set_target_properties(gmcc_deps::mpfi PROPERTIES IMPORTED_LOCATION "${GmccNumbers_MPFI_LIB}"
    INTERFACE_INCLUDE_DIRECTORIES "${GmccNumbers_MPFI_INCLUDE}"
    INTERFACE_LINK_LIBRARIES gmcc_deps::mpfr)
endif()
