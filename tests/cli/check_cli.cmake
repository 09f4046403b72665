# Runs sandbox-cli and checks its exit code and output (called by tests/cli/CMakeLists.txt).
# -DCLI=path -DARGS=a|b|c -DEXIT=code [-DSTDOUT=regex] [-DSTDERR=regex]
string(REPLACE "|" ";" args "${ARGS}")
execute_process(COMMAND ${CLI} ${args}
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 100)
set(report "sandbox-cli ${args}\nexit: ${rc}\nstdout:\n${out}\nstderr:\n${err}")
if(NOT rc STREQUAL "${EXIT}")
  message(FATAL_ERROR "expected exit ${EXIT}\n${report}")
endif()
if(NOT STDOUT STREQUAL "" AND NOT out MATCHES "${STDOUT}")
  message(FATAL_ERROR "stdout does not match '${STDOUT}'\n${report}")
endif()
if(NOT STDERR STREQUAL "" AND NOT err MATCHES "${STDERR}")
  message(FATAL_ERROR "stderr does not match '${STDERR}'\n${report}")
endif()
if(NOT EXIT STREQUAL "0" AND err STREQUAL "")
  message(FATAL_ERROR "a failure must say why on stderr\n${report}")
endif()
message(STATUS "${report}")
