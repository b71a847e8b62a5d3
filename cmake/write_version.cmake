# Writes the code version header (cmake/version.hpp.in) from `git describe`, at every build (the
# target stoneskip_version, on which every stoneskip target depends): a version taken only when
# CMake configures goes stale at the next commit, and every result file and report would then name
# code it was not made with (and a report's resume key, which holds it, would reuse sections of
# older code). configure_file rewrites the header only when its text changes, so an unchanged
# version recompiles nothing.
# Inputs: SOURCE_DIR, OUTPUT, PROJECT_VERSION.
execute_process(COMMAND git describe --always --dirty --tags
                WORKING_DIRECTORY ${SOURCE_DIR}
                OUTPUT_VARIABLE STONESKIP_GIT OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
if(NOT STONESKIP_GIT)
  set(STONESKIP_GIT "unknown")
endif()
configure_file(${SOURCE_DIR}/cmake/version.hpp.in ${OUTPUT} @ONLY)
