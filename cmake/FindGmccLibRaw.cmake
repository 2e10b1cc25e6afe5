# FindGmccLibRaw: LibRaw (Debian libraw-dev), thread-safe build libraw_r, for camera raw files
# (input/raw_file.h). Defines the imported target gmcc_deps::libraw.
include(${CMAKE_CURRENT_LIST_DIR}/GmccFindOne.cmake)
gmcc_find_one(GmccLibRaw libraw/libraw.h raw_r gmcc_deps::libraw)
