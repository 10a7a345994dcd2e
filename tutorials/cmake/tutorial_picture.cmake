# Runs one tutorial program (a solution, or a recorded wrong answer, which fails its check:
# its exit code is ignored here) with TUTORIAL_PICTURE_DIR=DIR, then either copies the
# picture it drew to DEST (MODE=update) or fails unless it shows the same pixels as DEST
# (MODE=check, decoded by SAME_PIXELS: the committed picture is the one the code draws
# today, whatever zlib compressed it).
#   cmake -DPROGRAM=... -DPICTURE=<name of the PNG it writes> -DDIR=... -DDEST=... -DMODE=update|check
#         [-DSAME_PIXELS=<same_pixels program>] -P
file(REMOVE ${DIR}/${PICTURE})
# (TUTORIAL_NN_SEED: the checks show their cases in a presentation drawn from a seed, and
# 07's picture records which rays its cache answered: a fixed one draws the same)
execute_process(COMMAND ${CMAKE_COMMAND} -E env TUTORIAL_PICTURE_DIR=${DIR} TUTORIAL_01_SEED=1 TUTORIAL_02_SEED=1 TUTORIAL_03_SEED=1
                        TUTORIAL_05_SEED=1 TUTORIAL_06_SEED=1 TUTORIAL_07_SEED=1 ${PROGRAM}
                OUTPUT_QUIET ERROR_QUIET RESULT_VARIABLE result)
if(NOT EXISTS ${DIR}/${PICTURE})
  message(FATAL_ERROR "${PROGRAM} drew no ${PICTURE} (exit ${result})")
endif()
if(MODE STREQUAL "update")
  file(COPY_FILE ${DIR}/${PICTURE} ${DEST})
  message(STATUS "${DEST}")
else()
  execute_process(COMMAND ${SAME_PIXELS} ${DIR}/${PICTURE} ${DEST} RESULT_VARIABLE differs)
  if(differs)
    message(FATAL_ERROR "${DEST} is not what ${PROGRAM} draws today (${DIR}/${PICTURE}): "
                        "run `cmake --build build --target tutorial-pictures` and commit the pictures")
  endif()
endif()
