# Run during the docs build: writes OUT/convergence_measured.md, a fragment the "error against run
# time" page includes. When `raycache convergence` exists it is run and its output (and
# its chart, when it can draw one) goes in; otherwise the fragment says so plainly.
# Inputs: -DRAYCACHE=<path of raycache> -DOUT=<folder>
set(scene cube:4)
# The subcommand exists when the tool's own help lists it
execute_process(COMMAND ${RAYCACHE} --help OUTPUT_VARIABLE tool_help ERROR_QUIET)
set(have FALSE)
if(tool_help MATCHES "\n  convergence ")
  execute_process(COMMAND ${RAYCACHE} convergence --help
                  RESULT_VARIABLE rc OUTPUT_VARIABLE help ERROR_QUIET)
  if(rc EQUAL 0)
    set(have TRUE)
  endif()
endif()
if(NOT have)
  file(WRITE ${OUT}/convergence_measured.md
"<b>Not measured in this build.</b> This build's <tt>raycache</tt> has no
<tt>convergence</tt> command yet (<tt>raycache --help</tt> does not list it), so this
page shows no measurements. When the command exists, the docs build runs it on
<tt>${scene}</tt> and puts its table and chart here.\n")
else()
  set(args convergence ${scene})
  set(shown "raycache convergence ${scene}")
  foreach(flag width height)
    if(help MATCHES "--${flag}")
      list(APPEND args --${flag} 128)
      string(APPEND shown " --${flag} 128")
    endif()
  endforeach()
  # Few samples, so that the docs build takes seconds, not minutes
  foreach(flag_value "spp|8" "ref-grid|8")
    string(REPLACE "|" ";" fv "${flag_value}")
    list(GET fv 0 flag)
    list(GET fv 1 value)
    if(help MATCHES "--${flag}")
      list(APPEND args --${flag} ${value})
      string(APPEND shown " --${flag} ${value}")
    endif()
  endforeach()
  list(APPEND args --csv ${OUT}/convergence.csv)
  string(APPEND shown " --csv convergence.csv")
  set(plot "")
  if(help MATCHES "--plot")
    list(APPEND args --plot ${OUT}/convergence.png)
    string(APPEND shown " --plot convergence.png")
    set(plot ${OUT}/convergence.png)
  endif()
  execute_process(COMMAND ${RAYCACHE} ${args}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "docs: `${shown}` failed (exit ${rc}):\n${err}")
  endif()
  string(REPLACE "${OUT}/" "" out "${out}")
  file(WRITE ${OUT}/convergence.txt "${out}")
  set(text "Measured during this docs build with\n\n\\verbatim\n${shown}\n\\endverbatim\n\n")
  string(APPEND text "\\verbinclude convergence.txt\n")
  if(plot AND EXISTS ${plot})
    string(APPEND text "\n\\image html convergence.png\n")
  endif()
  file(WRITE ${OUT}/convergence_measured.md "${text}")
endif()
