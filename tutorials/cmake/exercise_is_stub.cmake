# Fails unless EXERCISE is what scripts/student_edition.py writes from the hole STUB_OF
# with tutorial NN open: the exercise as committed is the stub of the library's function.
#   cmake -DSTUB_OF=... -DNN=.. -DEXERCISE=... -DSCRIPT=.../student_edition.py -P exercise_is_stub.cmake
find_program(PYTHON3 python3 REQUIRED)
execute_process(COMMAND ${PYTHON3} ${SCRIPT} stub ${STUB_OF} ${NN} OUTPUT_VARIABLE stub RESULT_VARIABLE failed)
file(READ ${EXERCISE} exercise)
if(failed OR NOT stub STREQUAL exercise)
  message(FATAL_ERROR "${EXERCISE} is not the stub of ${STUB_OF}: run\n"
                      "  python3 scripts/student_edition.py stub ${STUB_OF} ${NN} > ${EXERCISE}")
endif()
