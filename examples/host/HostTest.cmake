# cmake -P script of the aot.example_host test: the C host driving an AOT .so must print exactly
# the table `ladderjit run --engine interp` prints for the same inputs (issue 5 acceptance).
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
set(ENV{LADDERJIT_CACHE} off)
set(ENV{LADDERJIT_KEY_DIR} ${WORK}/keys) # compile's default signing key pair, not ~/.config

function(run_checked out)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE stdout ERROR_VARIABLE stderr)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "failed (${rc}): ${ARGN}\n${stderr}")
  endif()
  set(${out} "${stdout}" PARENT_SCOPE)
endfunction()

# The host sees nothing of the source tree: only what `cmake --install` puts in the prefix.
run_checked(ignored ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${WORK}/prefix)
if(NOT EXISTS ${WORK}/prefix/include/ladderjit/program.h)
  message(FATAL_ERROR "install did not provide include/ladderjit/program.h")
endif()
run_checked(ignored ${CC} -std=c11 -Wall -Wextra -Werror -I${WORK}/prefix/include
  ${HOST_SOURCE} -o ${WORK}/host -ldl)
set(HOST ${WORK}/host)
set(LADDERJIT ${WORK}/prefix/bin/ladderjit)
run_checked(ignored ${LADDERJIT} compile ${PROGRAM} -o ${WORK}/prog.so)
run_checked(host_table ${HOST} ${WORK}/prog.so 120 ${WORK}/host.stim ${WORK}/host.params)
run_checked(interp_table ${LADDERJIT} run ${PROGRAM} --engine interp --ticks 120
  --params ${WORK}/host.params --stimulus ${WORK}/host.stim --watch G2579,Y481,B0,D41)
if(NOT host_table STREQUAL interp_table)
  file(WRITE ${WORK}/host.csv "${host_table}")
  file(WRITE ${WORK}/interp.csv "${interp_table}")
  message(FATAL_ERROR "host and interpreter differ: compare ${WORK}/host.csv ${WORK}/interp.csv")
endif()
# The scenario must reach the interesting states, or the comparison proves little: at least
# three finished parts (B0 total >= 3) and a last cycle time (D41 > 0) in the final row.
string(REGEX MATCH "[0-9]+,-?[0-9]+,-?[0-9]+,(-?[0-9]+),(-?[0-9]+)\n$" last "${host_table}")
if(NOT last OR CMAKE_MATCH_1 LESS 3 OR CMAKE_MATCH_2 LESS 1)
  message(FATAL_ERROR "scenario too weak, last row: ${last}")
endif()
message(STATUS "host == interp over 120 ticks; last row ${last}")
