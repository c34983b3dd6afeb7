# Runs one bad-input case: `passlab <args>` with the case's expect.txt, then checks the exit code
# (a crash or signal never matches) and that every expected substring is in stderr.
# Invoked as: cmake -DPASSLAB=... -DCASE_DIR=... -DOUT_DIR=... -P run_case.cmake
file(STRINGS "${CASE_DIR}/expect.txt" lines)
set(expected_exit "")
set(substrings "")
foreach(line IN LISTS lines)
  if(line MATCHES "^args: (.*)$")
    set(args_text "${CMAKE_MATCH_1}")
  elseif(line MATCHES "^exit: ([0-9]+)$")
    set(expected_exit "${CMAKE_MATCH_1}")
  elseif(line MATCHES "^stderr: (.*)$")
    list(APPEND substrings "${CMAKE_MATCH_1}")
  endif()
endforeach()
file(RELATIVE_PATH rel_dir "${WORK_DIR}" "${CASE_DIR}")
string(REPLACE "{dir}" "${rel_dir}" args_text "${args_text}")
string(REPLACE "{out}" "${OUT_DIR}" args_text "${args_text}")
separate_arguments(args UNIX_COMMAND "${args_text}")
execute_process(COMMAND "${PASSLAB}" ${args}
                WORKING_DIRECTORY "${WORK_DIR}"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err
                TIMEOUT 60)
if(NOT rc STREQUAL expected_exit)
  message(FATAL_ERROR "passlab ${args_text}: exit '${rc}', expected ${expected_exit}\nstderr:\n${err}\nstdout:\n${out}")
endif()
foreach(s IN LISTS substrings)
  string(FIND "${err}${out}" "${s}" pos)
  if(pos EQUAL -1)
    message(FATAL_ERROR "passlab ${args_text}: output lacks\n  ${s}\nstderr:\n${err}")
  endif()
endforeach()
