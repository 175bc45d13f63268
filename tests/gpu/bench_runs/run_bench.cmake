# run_bench(<caustics-bench arguments>): runs ${BENCH} and fails the calling test on a non-zero exit or
# on any Vulkan validation message (the check scripts of this folder include it).
function(run_bench)
  execute_process(COMMAND "${BENCH}" ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "caustics-bench ${ARGV0} failed (${rc}):\n${out}\n${err}")
  endif()
  if(err MATCHES "validation:")
    message(FATAL_ERROR "validation messages during caustics-bench ${ARGV0}:\n${err}")
  endif()
endfunction()
