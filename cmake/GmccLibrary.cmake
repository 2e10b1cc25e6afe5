# gmcc_library(NAME <folder> SOURCES ...): one gmcc library target per top-level folder, with
# namespace = folder = target (gmcc::<folder>), its public headers under <folder>/include, and
# install/export rules.
function(gmcc_library)
  cmake_parse_arguments(ARG "" "NAME" "SOURCES" ${ARGN})
  set(target gmcc_${ARG_NAME})
  add_library(${target} ${ARG_SOURCES})
  add_library(gmcc::${ARG_NAME} ALIAS ${target})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${ARG_NAME} OUTPUT_NAME ${target}
    POSITION_INDEPENDENT_CODE ON)
  target_include_directories(${target} PUBLIC
    $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  target_compile_features(${target} PUBLIC cxx_std_17)
  # gmcc::numerics' internals (numerics/internal: double-word arithmetic, the filters' constants,
  # checks): the libraries' sources, tests, benchmarks and fuzz targets read them in the build
  # tree; they are not installed, and an installed gmcc's targets do not name them.
  target_link_libraries(${target} PUBLIC $<BUILD_INTERFACE:gmcc_numerics_internal>)
  if(GMCC_SANITIZE)
    # An instrumented static library needs the sanitizer runtimes wherever it is linked,
    # including in projects that find_package(gmcc) from an instrumented install.
    target_link_options(${target} INTERFACE ${GMCC_SANITIZE_LINK_FLAGS})
  endif()
  install(TARGETS ${target} EXPORT gmccTargets
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
  install(DIRECTORY include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
endfunction()
