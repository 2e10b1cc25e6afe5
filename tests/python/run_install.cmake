# Install gmcc into a scratch prefix and import the Python package from a clean environment with
# only PYTHONPATH set, as the README's one line does; check the version and that the shipped data
# came along (gmcc.data_dir() inside the installed package).
# Arguments: -DGMCC_BUILD=<gmcc build dir> -DPYTHON=<python3> -DWORK=<scratch dir>
file(REMOVE_RECURSE "${WORK}")
execute_process(COMMAND ${CMAKE_COMMAND} --install "${GMCC_BUILD}" --prefix "${WORK}/prefix"
                OUTPUT_QUIET RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cmake --install failed (${rc})")
endif()
set(site "${WORK}/prefix/lib/python3/dist-packages")
execute_process(
  COMMAND env -i PATH=/usr/bin:/bin PYTHONDONTWRITEBYTECODE=1 PYTHONPATH=${site} ${PYTHON} -c
          "import gmcc, os; print(gmcc.__version__); print(os.path.realpath(gmcc.__file__)); print(os.path.realpath(gmcc.data_dir())); print(gmcc.select([[1,1,1],[2,1,1],[1,2,1]], [[1,1,1]]).kind)"
  WORKING_DIRECTORY "${WORK}"
  OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "import gmcc from the installed prefix failed (${rc}): ${err}")
endif()
file(REAL_PATH "${site}" real_site)
string(REPLACE "\n" ";" lines "${out}")
list(GET lines 0 version)
list(GET lines 1 file)
list(GET lines 2 data)
list(GET lines 3 kind)
if(NOT version MATCHES "^[0-9]+\\.[0-9]+\\.[0-9]+$")
  message(FATAL_ERROR "gmcc.__version__ is '${version}'")
endif()
if(NOT file MATCHES "^${real_site}/gmcc/" OR NOT data STREQUAL "${real_site}/gmcc/data")
  message(FATAL_ERROR "imported ${file} with data ${data}, not from ${real_site}")
endif()
if(NOT kind STREQUAL "polygon")
  message(FATAL_ERROR "select in the installed module gave '${kind}'")
endif()
message(STATUS "installed gmcc ${version} imports from ${real_site}")
