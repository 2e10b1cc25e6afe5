# Install gmcc into a scratch prefix, then configure, build and run a consumer project against it.
# Arguments: -DGMCC_BUILD=<gmcc build dir> -DCONSUMER_SRC=<consumer source> -DWORK=<scratch dir>
file(REMOVE_RECURSE "${WORK}")
include(${CMAKE_CURRENT_LIST_DIR}/step.cmake)
step(${CMAKE_COMMAND} --install "${GMCC_BUILD}" --prefix "${WORK}/prefix")
# Eigen and Google Benchmark hidden: the installed package must not need them.
# -DCORE_ONLY=ON: the consumer asks for the core components, and the file formats' libraries are
# hidden too (a geometry-only consumer must configure and build without them).
set(core_flags "")
if(CORE_ONLY)
  set(core_flags -DCORE_ONLY=ON -DCMAKE_DISABLE_FIND_PACKAGE_PNG=ON -DCMAKE_DISABLE_FIND_PACKAGE_TIFF=ON
      -DCMAKE_DISABLE_FIND_PACKAGE_GmccLibRaw=ON -DCMAKE_DISABLE_FIND_PACKAGE_GmccNettle=ON)
endif()
step(${CMAKE_COMMAND} -S "${CONSUMER_SRC}" -B "${WORK}/build" -G Ninja
     -DCMAKE_BUILD_TYPE=Release "-DCMAKE_PREFIX_PATH=${WORK}/prefix"
     -DCMAKE_DISABLE_FIND_PACKAGE_Eigen3=ON -DCMAKE_DISABLE_FIND_PACKAGE_benchmark=ON ${core_flags})
step(${CMAKE_COMMAND} --build "${WORK}/build")
step("${WORK}/build/consumer")
file(GLOB_RECURSE exported "${WORK}/prefix/*.cmake")
foreach(f ${exported})
  file(READ "${f}" text)
  if(text MATCHES "Eigen|benchmark")
    message(FATAL_ERROR "the installed package names Eigen or Google Benchmark: ${f}")
  endif()
endforeach()
# The routes only tests, fuzz targets and benchmarks use (gmcc_test_support, tests/support/) are
# not in the installed libraries: neither the oracles' names nor the test-support library.
file(GLOB_RECURSE installed_libraries "${WORK}/prefix/*libgmcc_*.a" "${WORK}/prefix/*libgmcc_*.so")
if(NOT installed_libraries)
  message(FATAL_ERROR "no gmcc library installed under ${WORK}/prefix")
endif()
foreach(lib ${installed_libraries})
  if(lib MATCHES "test_support")
    message(FATAL_ERROR "the test-support library is installed: ${lib}")
  endif()
  file(STRINGS "${lib}" oracles REGEX "convex_hull_cgal|feasible_set_3d_reference")
  if(oracles)
    message(FATAL_ERROR "an installed library holds a test-only route: ${lib}")
  endif()
endforeach()
