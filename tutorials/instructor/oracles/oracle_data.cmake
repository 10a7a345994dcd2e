# Runs a tutorial's recording program (its check, the reference solution and the
# instructor's oracles, each answer recorded) and either writes the data to DATA
# (MODE=update) or fails unless DATA, the file the student edition ships, equals what the
# oracles answer today (MODE=check).
#   cmake -DPROGRAM=... -DOUT=<file to record to> -DDATA=<tutorial's oracle_data.txt> -DMODE=update|check -P
file(REMOVE ${OUT})
execute_process(COMMAND ${CMAKE_COMMAND} -E env TUTORIAL_ORACLE_RECORD=${OUT} TUTORIAL_PICTURE_DIR=${OUT}.pictures
                        ${PROGRAM}
                OUTPUT_VARIABLE output ERROR_VARIABLE output RESULT_VARIABLE result)
if(NOT result EQUAL 0 OR NOT EXISTS ${OUT})
  message(FATAL_ERROR "${PROGRAM} (the reference solution with the oracles) failed (exit ${result}):\n${output}")
endif()
if(MODE STREQUAL "update")
  file(COPY_FILE ${OUT} ${DATA})
  message(STATUS "${DATA}")
else()
  execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUT} ${DATA} RESULT_VARIABLE differs)
  if(differs)
    message(FATAL_ERROR "${DATA} is not what the oracles answer today (${OUT}): run "
                        "`cmake --build build --target tutorial-data` and commit the data")
  endif()
  message(STATUS "${DATA} equals the oracles' answers")
endif()
