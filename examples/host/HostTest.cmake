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
get_filename_component(host_dir ${HOST_SOURCE} DIRECTORY)
run_checked(ignored ${CC} -std=c11 -Wall -Wextra -Werror -I${WORK}/prefix/include -I${host_dir}
  ${HOST_SOURCE} ${VERIFY_SOURCE} -o ${WORK}/host -lcrypto -ldl)
set(HOST ${WORK}/host)
set(LADDERJIT ${WORK}/prefix/bin/ladderjit)
run_checked(ignored ${LADDERJIT} compile ${PROGRAM} -o ${WORK}/prog.so)
set(key ${WORK}/keys/aot-signing.pub) # the default pair `compile` just created
run_checked(host_table ${HOST} ${WORK}/prog.so ${key} 120 ${WORK}/host.stim ${WORK}/host.params)
# The host verifies like ladderjit does: a .so with one byte changed, or one signed by another
# key, is refused (exit 2) before it is loaded.
file(COPY_FILE ${WORK}/prog.so ${WORK}/bad.so)
# 16 bytes at offset 1000 overwritten with the ELF header's first 16 (which differ from them).
execute_process(COMMAND dd if=${WORK}/prog.so of=${WORK}/bad.so bs=1 seek=1000 count=16
  conv=notrunc RESULT_VARIABLE rc OUTPUT_QUIET ERROR_QUIET)
execute_process(COMMAND ${HOST} ${WORK}/bad.so ${key} 5 ${WORK}/b.stim ${WORK}/b.params
  RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_QUIET)
if(NOT rc EQUAL 2 OR NOT err MATCHES "bad signature")
  message(FATAL_ERROR "host accepted a modified .so (exit ${rc}): ${err}")
endif()
run_checked(ignored ${LADDERJIT} keygen -o ${WORK}/other)
execute_process(COMMAND ${HOST} ${WORK}/prog.so ${WORK}/other.pub 5 ${WORK}/b.stim ${WORK}/b.params
  RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_QUIET)
if(NOT rc EQUAL 2 OR NOT err MATCHES "not the trusted one")
  message(FATAL_ERROR "host accepted a .so signed by another key (exit ${rc}): ${err}")
endif()
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
