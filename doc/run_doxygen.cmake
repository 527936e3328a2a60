# Runs Doxygen for the `doc` target: cmake -DDOXYGEN=... -DDOXYFILE=...
# -DWARNINGS=<log> -DOUTPUT=<html/index.html> -DFAIL=<ON|OFF> -P run_doxygen.cmake
# Prints the warnings, and on failure removes OUTPUT so that the next build
# runs Doxygen again instead of taking the manual as up to date.
file(REMOVE "${WARNINGS}")
execute_process(COMMAND "${DOXYGEN}" "${DOXYFILE}" RESULT_VARIABLE result)
set(warnings "")
if(EXISTS "${WARNINGS}")
  file(READ "${WARNINGS}" warnings)
endif()
if(NOT result EQUAL 0 OR (FAIL AND NOT warnings STREQUAL ""))
  file(REMOVE "${OUTPUT}")
  message(FATAL_ERROR "Doxygen failed (exit ${result}); warnings (${WARNINGS}):\n${warnings}")
elseif(NOT warnings STREQUAL "")
  message(WARNING "Doxygen warnings (${WARNINGS}):\n${warnings}")
endif()
