# Runs a tool during the docs build and saves what it prints, with the tool's build path
# shortened to its name (so that "Usage: /long/build/path/raycache" reads "Usage: raycache").
# Inputs: -DEXE=<program> -DARGS=<arguments, separated by |> -DOUT=<file>
string(REPLACE "|" ";" args "${ARGS}")
execute_process(COMMAND ${EXE} ${args} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "docs: `${EXE} ${args}` failed (exit ${rc}):\n${err}")
endif()
get_filename_component(name ${EXE} NAME)
string(REPLACE "${EXE}" "${name}" out "${out}")
file(WRITE ${OUT} "${out}")
