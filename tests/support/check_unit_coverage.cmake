# The per-file unit entries (tests/CMakeLists.txt) name every top-level test unit of gmcc_tests:
# `gmcc_tests --list_content` lists the top-level units unindented; each must be in ENTRIES (one
# name per line), or a suite would go unrun by ctest.
#   cmake -DTESTS=gmcc_tests -DENTRIES=unit_entries.txt -P check_unit_coverage.cmake
execute_process(COMMAND ${TESTS} --list_content OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "gmcc_tests --list_content failed (${rc})")
endif()
file(STRINGS ${ENTRIES} entries)
string(REPLACE "\n" ";" listed "${out}${err}")
set(missing "")
set(count 0)
foreach(line IN LISTS listed)
  if(line MATCHES "^([A-Za-z0-9_]+)\\*?$")
    math(EXPR count "${count} + 1")
    list(FIND entries ${CMAKE_MATCH_1} at)
    if(at EQUAL -1)
      list(APPEND missing ${CMAKE_MATCH_1})
    endif()
  endif()
endforeach()
if(count EQUAL 0)
  message(FATAL_ERROR "gmcc_tests --list_content listed no top-level unit")
endif()
if(missing)
  message(FATAL_ERROR "top-level test units no ctest entry runs: ${missing} (tests/CMakeLists.txt reads "
                      "BOOST_AUTO_TEST_SUITE and test-case lines at the start of a line)")
endif()
message(STATUS "${count} top-level test units, each run by a unit_* entry")
