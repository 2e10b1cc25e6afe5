# FindGmccNettle: Nettle's SHA-256, for the input checksums in gmcc's provenance records.
# Defines the imported target gmcc_deps::nettle.
include(${CMAKE_CURRENT_LIST_DIR}/GmccFindOne.cmake)
gmcc_find_one(GmccNettle nettle/sha2.h nettle gmcc_deps::nettle)
