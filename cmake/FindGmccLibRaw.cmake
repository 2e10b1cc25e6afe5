# FindGmccLibRaw: LibRaw (Debian libraw-dev), thread-safe build libraw_r, for camera raw files
# (input/raw_file.h). Defines the imported target gmcc_deps::libraw.
include(FindPackageHandleStandardArgs)
find_path(GmccLibRaw_INCLUDE libraw/libraw.h)
find_library(GmccLibRaw_LIB raw_r)
find_package_handle_standard_args(GmccLibRaw REQUIRED_VARS GmccLibRaw_INCLUDE GmccLibRaw_LIB)
if(GmccLibRaw_FOUND AND NOT TARGET gmcc_deps::libraw)
  add_library(gmcc_deps::libraw UNKNOWN IMPORTED)
  set_target_properties(gmcc_deps::libraw PROPERTIES IMPORTED_LOCATION "${GmccLibRaw_LIB}"
    INTERFACE_INCLUDE_DIRECTORIES "${GmccLibRaw_INCLUDE}")
endif()
