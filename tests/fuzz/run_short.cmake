# Runs a fuzzer for a short time over its seeds, in a scratch directory: the fuzzer grows
# the first corpus directory it is given, and that must not be the repository's.
#   -DFUZZER=path -DSCRATCH=dir -DSEEDS=dir;dir... -DARGS=arg;arg...
file(REMOVE_RECURSE ${SCRATCH})
file(MAKE_DIRECTORY ${SCRATCH}/corpus)
execute_process(
  COMMAND ${FUZZER} -artifact_prefix=${SCRATCH}/ ${ARGS} ${SCRATCH}/corpus ${SEEDS}
  RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  file(GLOB artifacts ${SCRATCH}/crash-* ${SCRATCH}/leak-* ${SCRATCH}/timeout-* ${SCRATCH}/oom-*)
  message(FATAL_ERROR "${FUZZER} found something (exit status ${status}): ${artifacts}")
endif()
