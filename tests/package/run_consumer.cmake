# Install gmcc into a scratch prefix, then configure, build and run a consumer project against it.
# Arguments: -DGMCC_BUILD=<gmcc build dir> -DCONSUMER_SRC=<consumer source> -DWORK=<scratch dir>
file(REMOVE_RECURSE "${WORK}")
function(step)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "step failed (${rc}): ${ARGN}")
  endif()
endfunction()
step(${CMAKE_COMMAND} --install "${GMCC_BUILD}" --prefix "${WORK}/prefix")
step(${CMAKE_COMMAND} -S "${CONSUMER_SRC}" -B "${WORK}/build" -G Ninja
     -DCMAKE_BUILD_TYPE=Release "-DCMAKE_PREFIX_PATH=${WORK}/prefix")
step(${CMAKE_COMMAND} --build "${WORK}/build")
step("${WORK}/build/consumer")
