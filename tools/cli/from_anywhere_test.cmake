# stoneskip works from any working directory. Oracles: the exit status, the files a report is
# (index.md, data.h5), and `stoneskip --version`, which names the shipped cases it found.
#  1. The built binary, started in a folder outside the source tree, runs a shipped throw
#     (`cases/...` found through the source tree recorded at build time).
#  2. `cmake --install` into a fresh prefix gives P/bin/stoneskip, whose shipped cases are
#     P/share/stoneskip/cases (not the source tree), and which runs the quick waves report into
#     `elsewhere/waves` (a folder that does not exist yet) and a shipped throw from that outside folder.
#  3. `regress --update` there rewrites no shipped baseline: refused, exit 2, the file unchanged.
# Run by ctest: cmake -DBUILD_DIR=.. -DSOURCE_DIR=.. -DSTONESKIP=.. -DWORK=.. -P from_anywhere_test.cmake
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/cwd)  # `elsewhere` is not made here: the report makes its missing parent

function(run_checked what)
  execute_process(COMMAND ${ARGN} WORKING_DIRECTORY ${WORK}/cwd RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${what}: exit ${rc}\n${out}\n${err}")
  endif()
  set(RAN_OUTPUT "${out}" PARENT_SCOPE)
endfunction()

function(require_report dir)
  foreach(f index.md data.h5)
    if(NOT EXISTS ${dir}/${f})
      message(FATAL_ERROR "${dir}/${f} was not written")
    endif()
  endforeach()
endfunction()

# 1. The built binary (a shipped throw from the outside folder; the quick report is run once, by
#    the installed binary below, to keep the test short).
run_checked("built stoneskip --version" ${STONESKIP} --version)
string(FIND "${RAN_OUTPUT}" "shipped cases: ${SOURCE_DIR}/cases" at)
if(at EQUAL -1)
  message(FATAL_ERROR "the built binary should find the source tree's cases; --version says:\n${RAN_OUTPUT}")
endif()
run_checked("built stoneskip run" ${STONESKIP} run cases/paper_8ms_spin.toml --json)
string(FIND "${RAN_OUTPUT}" "\"bounces\"" at)
if(at EQUAL -1)
  message(FATAL_ERROR "built stoneskip run printed no bounce count:\n${RAN_OUTPUT}")
endif()

# 2. The installed binary.
run_checked("cmake --install" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${WORK}/prefix)
set(installed ${WORK}/prefix/bin/stoneskip)
run_checked("installed stoneskip --version" ${installed} --version)
string(FIND "${RAN_OUTPUT}" "shipped cases: ${WORK}/prefix/share/stoneskip/cases" at)
if(at EQUAL -1)
  message(FATAL_ERROR "the installed binary should find its own shipped cases; --version says:\n${RAN_OUTPUT}")
endif()
run_checked("installed stoneskip report waves --quick" ${installed} report waves --quick --out elsewhere/waves)
require_report(${WORK}/cwd/elsewhere/waves)
run_checked("installed stoneskip run" ${installed} run cases/paper_8ms_spin.toml --json)
string(FIND "${RAN_OUTPUT}" "\"bounces\"" at)
if(at EQUAL -1)
  message(FATAL_ERROR "installed stoneskip run printed no bounce count:\n${RAN_OUTPUT}")
endif()

# 3. `regress --update` from the outside folder rewrites no shipped baseline (it replaced the
#    installed ones until December 5): with no --baseline, and with a shipped one named by its
#    relative path, it is bad input (exit 2) before any work, and the installed file is unchanged.
set(shipped_baseline ${WORK}/prefix/share/stoneskip/cases/baselines/spin_paper_realtime.toml)
file(SHA256 ${shipped_baseline} before)
foreach(args "regress;--update" "regress;--update;--baseline;cases/baselines/spin_paper_realtime.toml")
  execute_process(COMMAND ${installed} ${args} WORKING_DIRECTORY ${WORK}/cwd RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 2)
    message(FATAL_ERROR "installed stoneskip ${args} from an outside folder: exit ${rc}, not 2\n${out}\n${err}")
  endif()
  string(FIND "${err}" "shipped cop" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "installed stoneskip ${args}: the refusal should say the shipped copies are not rewritten:\n${err}")
  endif()
endforeach()
file(SHA256 ${shipped_baseline} after)
if(NOT before STREQUAL after)
  message(FATAL_ERROR "regress --update from an outside folder changed the installed ${shipped_baseline}")
endif()
file(REMOVE_RECURSE ${WORK})
