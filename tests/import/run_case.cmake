# One import case: passlab import CASE_DIR/src* -o OUT_DIR, append tests.toml, passlab test.
# (src.vs beside src.fs is the ISF vertex companion, not a second source.)
file(GLOB src LIST_DIRECTORIES true "${CASE_DIR}/src*")
list(FILTER src EXCLUDE REGEX "\\.vs$")  # an ISF vertex companion goes with its .fs
list(LENGTH src n)
if(NOT n EQUAL 1)
  message(FATAL_ERROR "${CASE_DIR}: expected exactly one src* source, found ${n}")
endif()
file(REMOVE_RECURSE "${OUT_DIR}")
execute_process(COMMAND "${PASSLAB}" import "${src}" -o "${OUT_DIR}" --no-golden
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "passlab import ${src}: exit ${rc}\n${err}")
endif()
file(READ "${CASE_DIR}/tests.toml" cases)
file(APPEND "${OUT_DIR}/preset.toml" "\n# --- cases from ${CASE_DIR}/tests.toml ---\n${cases}")
execute_process(COMMAND "${PASSLAB}" test "${OUT_DIR}" --fail-dir "${OUT_DIR}/failures"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "passlab test ${OUT_DIR}: exit ${rc}\n${out}\n${err}")
endif()
