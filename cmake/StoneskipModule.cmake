# stoneskip_module(NAME DIR <dir> [DEPS ...] [TEST_DEPS ...])
#
# One module = one folder. Every *.cpp in DIR goes into the static library NAME, except:
#   *_test.cpp   -> one Boost.Test executable NAME_tests, registered with ctest;
#   *_bench.cpp  -> one Google Benchmark executable NAME_bench;
#   *_fuzz.cpp   -> one libFuzzer target each (STONESKIP_FUZZERS=ON, clang) and, always, a corpus
#                   replay test built with any compiler (<dir>/fuzz_corpus/<stem>/).
# Adding a file needs no CMake edit (CONFIGURE_DEPENDS re-globs on build).
function(stoneskip_module name)
  cmake_parse_arguments(A "" "DIR" "DEPS;TEST_DEPS" ${ARGN})
  file(GLOB all CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/${A_DIR}/*.cpp)
  set(tests ${all})
  list(FILTER tests INCLUDE REGEX "_test\\.cpp$")
  set(benches ${all})
  list(FILTER benches INCLUDE REGEX "_bench\\.cpp$")
  set(fuzzers ${all})
  list(FILTER fuzzers INCLUDE REGEX "_fuzz\\.cpp$")
  set(srcs ${all})
  list(FILTER srcs EXCLUDE REGEX "_(test|bench|fuzz)\\.cpp$")
  if(srcs)
    add_library(${name} STATIC ${srcs})
    target_link_libraries(${name} PUBLIC stoneskip_options ${A_DEPS})
    add_dependencies(${name} stoneskip_version)  # the version header, current at every build
  else()
    add_library(${name} INTERFACE)
    target_link_libraries(${name} INTERFACE stoneskip_options ${A_DEPS})
  endif()
  if(tests)
    add_executable(${name}_tests ${tests} ${PROJECT_SOURCE_DIR}/cmake/test_main.cpp)
    target_link_libraries(${name}_tests PRIVATE ${name} Boost::unit_test_framework ${A_TEST_DEPS})
    target_compile_definitions(${name}_tests PRIVATE BOOST_TEST_DYN_LINK)
    add_test(NAME ${name} COMMAND ${name}_tests --report_level=short --color_output=no
             WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
  endif()
  if(benches AND STONESKIP_BENCHMARKS)
    add_executable(${name}_bench ${benches})
    target_link_libraries(${name}_bench PRIVATE ${name} benchmark::benchmark_main ${A_TEST_DEPS})
  endif()
  foreach(f ${fuzzers})
    get_filename_component(stem ${f} NAME_WE)
    add_executable(${stem}_replay ${f} ${PROJECT_SOURCE_DIR}/cmake/fuzz_replay_main.cpp)
    target_link_libraries(${stem}_replay PRIVATE ${name})
    add_test(NAME ${stem}_corpus COMMAND ${stem}_replay ${CMAKE_CURRENT_SOURCE_DIR}/${A_DIR}/fuzz_corpus/${stem}
             WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
    if(STONESKIP_FUZZERS)
      add_executable(${stem} ${f})
      target_compile_options(${stem} PRIVATE -fsanitize=fuzzer,address,undefined)
      target_link_options(${stem} PRIVATE -fsanitize=fuzzer,address,undefined)
      target_link_libraries(${stem} PRIVATE ${name})
    endif()
  endforeach()
endfunction()
