# Run during the docs build: when `raycache SUB` exists, runs `raycache SUB ARGS` and writes
# OUT/NAME.txt (its output) and OUT/NAME_measured.md (a fragment that states the command
# and includes the output); otherwise the fragment says plainly that nothing was measured.
# Inputs: -DRAYCACHE=<path> -DSUB=<subcommand> -DARGS=<arguments separated by |>
#         -DNAME=<file stem> -DOUT=<folder>
string(REPLACE "|" ";" args "${ARGS}")
string(REPLACE ";" " " shown "raycache ${SUB};${args}")
execute_process(COMMAND ${RAYCACHE} --help OUTPUT_VARIABLE tool_help ERROR_QUIET)
if(NOT tool_help MATCHES "\n  ${SUB} ")
  file(WRITE ${OUT}/${NAME}_measured.md
"<b>Not measured in this build:</b> this build's <tt>raycache</tt> has no <tt>${SUB}</tt>
command (<tt>raycache --help</tt> does not list it).\n")
  return()
endif()
execute_process(COMMAND ${RAYCACHE} ${SUB} ${args}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "docs: `${shown}` failed (exit ${rc}):\n${err}")
endif()
string(REPLACE "${OUT}/" "" out "${out}")
file(WRITE ${OUT}/${NAME}.txt "${out}")
file(WRITE ${OUT}/${NAME}_measured.md
     "Measured during this docs build with\n\n\\verbatim\n${shown}\n\\endverbatim\n\n\\verbinclude ${NAME}.txt\n")
