# Run during the docs build: writes OUT/stochastic_measured.md, the fragment the distributed
# ray tracing page includes: `raycache convergence --stochastic` on a small image (64x64,
# 1 to 16 samples per pixel, one run each: about 10 s of the docs build), its table and chart.
# Inputs: -DRAYCACHE=<path of raycache> -DOUT=<folder>
set(args convergence cube:4 --stochastic --width 64 --height 64 --spp 16 --ref-spp 64 --repeat 1)
string(REPLACE ";" " " shown "raycache ${args}")
execute_process(COMMAND ${RAYCACHE} ${args} --csv ${OUT}/stochastic.csv --plot ${OUT}/stochastic.png
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "docs: `${shown}` failed (exit ${rc}):\n${err}")
endif()
string(REPLACE "${OUT}/" "" out "${out}")
file(WRITE ${OUT}/stochastic.txt "${out}")
set(text "Measured during this docs build with\n\n\\verbatim\n${shown} --csv stochastic.csv --plot stochastic.png\n\\endverbatim\n\n")
string(APPEND text "\\verbinclude stochastic.txt\n\n")
if(EXISTS ${OUT}/stochastic.png)
  string(APPEND text "\\image html stochastic.png\n")
endif()
file(WRITE ${OUT}/stochastic_measured.md "${text}")
