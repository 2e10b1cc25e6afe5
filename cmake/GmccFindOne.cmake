# gmcc_find_one(NAME HEADER LIBRARY TARGET): the find module of one library with one header, for
# FindGmccNettle and FindGmccLibRaw. Finds HEADER and LIBRARY, sets NAME_FOUND (and NAME_INCLUDE,
# NAME_LIB) and defines the imported target TARGET. A macro: the results are the caller's.
include(FindPackageHandleStandardArgs)
macro(gmcc_find_one name header library target)
  find_path(${name}_INCLUDE ${header})
  find_library(${name}_LIB ${library})
  find_package_handle_standard_args(${name} REQUIRED_VARS ${name}_INCLUDE ${name}_LIB)
  if(${name}_FOUND AND NOT TARGET ${target})
    add_library(${target} UNKNOWN IMPORTED)
    set_target_properties(${target} PROPERTIES IMPORTED_LOCATION "${${name}_LIB}"
      INTERFACE_INCLUDE_DIRECTORIES "${${name}_INCLUDE}")
  endif()
endmacro()
