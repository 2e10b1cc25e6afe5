# Configure, build and run tests/package/subproject: gmcc as a parent project's add_subdirectory.
# Arguments: -DGMCC_SOURCE=<gmcc source> -DWORK=<scratch dir>. The parent asks for Release (the
# objects are those of gmcc's own Release build, so ccache serves most of them) and checks that
# gmcc kept it.
file(REMOVE_RECURSE "${WORK}")
include(${CMAKE_CURRENT_LIST_DIR}/step.cmake)
step(${CMAKE_COMMAND} -S "${GMCC_SOURCE}/tests/package/subproject" -B "${WORK}" -G Ninja
     -DCMAKE_BUILD_TYPE=Release "-DGMCC_SOURCE=${GMCC_SOURCE}")
step(${CMAKE_COMMAND} --build "${WORK}" --target consumer)
step("${WORK}/consumer")
