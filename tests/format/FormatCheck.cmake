# Runs clang-format --dry-run --Werror over the tracked C/C++ sources; fails listing the files
# whose formatting differs.
execute_process(COMMAND ${GIT} ls-files -- "*.c" "*.h" "*.cpp"
  WORKING_DIRECTORY ${SOURCE_DIR} OUTPUT_VARIABLE files OUTPUT_STRIP_TRAILING_WHITESPACE
  RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "git ls-files failed")
endif()
string(REPLACE "\n" ";" files "${files}")
set(bad "")
foreach(f IN LISTS files)
  execute_process(COMMAND ${CLANG_FORMAT} --dry-run --Werror ${f}
    WORKING_DIRECTORY ${SOURCE_DIR} RESULT_VARIABLE r OUTPUT_QUIET ERROR_QUIET)
  if(NOT r EQUAL 0)
    list(APPEND bad ${f})
  endif()
endforeach()
list(LENGTH files n)
if(bad)
  list(JOIN bad "\n  " badText)
  message(FATAL_ERROR "not clang-formatted (run clang-format -i):\n  ${badText}")
endif()
message(STATUS "${n} files clang-formatted")
