# FindGmccNettle: Nettle's SHA-256, for the input checksums in gmcc's provenance records.
# Defines the imported target gmcc_deps::nettle.
include(FindPackageHandleStandardArgs)
find_path(GmccNettle_INCLUDE nettle/sha2.h)
find_library(GmccNettle_LIB nettle)
find_package_handle_standard_args(GmccNettle REQUIRED_VARS GmccNettle_INCLUDE GmccNettle_LIB)
if(GmccNettle_FOUND AND NOT TARGET gmcc_deps::nettle)
  add_library(gmcc_deps::nettle UNKNOWN IMPORTED)
  set_target_properties(gmcc_deps::nettle PROPERTIES IMPORTED_LOCATION "${GmccNettle_LIB}"
    INTERFACE_INCLUDE_DIRECTORIES "${GmccNettle_INCLUDE}")
endif()
