# Sanitizer and fuzzing builds (scripts/test-sanitize, fuzz/README.md). The flags apply to every
# gmcc target; GMP, MPFR, MPFI and Boost stay uninstrumented (their memory is still checked where
# it crosses malloc and free). -fno-sanitize-recover makes any undefined behaviour abort, so a
# test that meets it fails instead of printing a warning nobody reads.
set(GMCC_SANITIZE_LINK_FLAGS -fsanitize=address,undefined)
if(GMCC_SANITIZE OR GMCC_FUZZ)
  add_compile_options(-fsanitize=address,undefined -fno-sanitize-recover=all
                      -fno-omit-frame-pointer)
  add_link_options(${GMCC_SANITIZE_LINK_FLAGS})
endif()
if(GMCC_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR "GMCC_FUZZ needs clang's libFuzzer: configure with "
                        "-DCMAKE_CXX_COMPILER=clang++-14 (fuzz/README.md)")
  endif()
  # Coverage instrumentation everywhere; only the fuzz targets link libFuzzer's main.
  add_compile_options(-fsanitize=fuzzer-no-link)
endif()
