# Read by cpack before it packages (CPACK_PROJECT_CONFIG_FILE): the .deb's Depends, from
# dpkg-shlibdeps run on the package's executables (listed in CPACK_RAYCACHE_BINARIES_FILE),
# the same line CPack's SHLIBDEPS gives. Without dpkg-shlibdeps, CPack's SHLIBDEPS does it.
if(NOT CPACK_GENERATOR STREQUAL "DEB")
  return()
endif()
find_program(RAYCACHE_DPKG_SHLIBDEPS dpkg-shlibdeps)
if(NOT RAYCACHE_DPKG_SHLIBDEPS OR NOT EXISTS "${CPACK_RAYCACHE_BINARIES_FILE}")
  set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
  return()
endif()
file(STRINGS "${CPACK_RAYCACHE_BINARIES_FILE}" _binaries)
set(_args "")
foreach(_binary IN LISTS _binaries)
  list(APPEND _args "-e${_binary}")
endforeach()
# dpkg-shlibdeps reads a debian/control, which may be empty
string(RANDOM LENGTH 8 _tag)
set(_work "${CPACK_PACKAGE_DIRECTORY}/_CPack_Packages/shlibdeps-${_tag}")
file(MAKE_DIRECTORY "${_work}/debian")
file(TOUCH "${_work}/debian/control")
execute_process(COMMAND ${RAYCACHE_DPKG_SHLIBDEPS} -O ${_args} WORKING_DIRECTORY "${_work}"
                OUTPUT_VARIABLE _out ERROR_VARIABLE _err RESULT_VARIABLE _result)
file(REMOVE_RECURSE "${_work}")
if(NOT _result EQUAL 0 OR NOT _out MATCHES "shlibs:Depends=([^\n]*)")
  message(FATAL_ERROR "dpkg-shlibdeps failed on ${_binaries}: ${_err}")
endif()
set(CPACK_DEBIAN_PACKAGE_DEPENDS "${CMAKE_MATCH_1}")
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS OFF)
