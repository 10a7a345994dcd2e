# What `cpack -G DEB` puts in the package (and `cmake --install` installs): the command-line
# tool, the GUI when it is built, the SPD scenes, the tours, the docs site and the web edition
# when they are built. Build the docs target (and, for the web page, the tests with Emscripten
# and Chromium) before packaging.
include(GNUInstallDirs)
if(TARGET raycache)
  install(TARGETS raycache RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()
if(TARGET raycache-gui)
  install(TARGETS raycache-gui RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()
install(DIRECTORY ${CMAKE_SOURCE_DIR}/scenes/ DESTINATION ${CMAKE_INSTALL_DATADIR}/raycache/scenes)
if(EXISTS ${CMAKE_SOURCE_DIR}/tours)
  install(DIRECTORY ${CMAKE_SOURCE_DIR}/tours/ DESTINATION ${CMAKE_INSTALL_DATADIR}/raycache/tours)
endif()
# /usr/share/doc/raycache, the package's name (CMAKE_INSTALL_DOCDIR would take the project's, RayCache)
install(DIRECTORY ${CMAKE_BINARY_DIR}/docs/html/ DESTINATION ${CMAKE_INSTALL_DATAROOTDIR}/doc/raycache/html OPTIONAL)
install(DIRECTORY ${CMAKE_BINARY_DIR}/web-edition/web/ DESTINATION ${CMAKE_INSTALL_DATADIR}/raycache/web OPTIONAL
  FILES_MATCHING PATTERN "*.html" PATTERN "*.js" PATTERN "*.css" PATTERN "CMakeFiles" EXCLUDE)

set(CPACK_PACKAGE_NAME raycache)
set(CPACK_PACKAGE_VENDOR "RayCache")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
    "Hanrahan's caching and breadth-first search for ray tracing, to run, step and measure")
set(CPACK_PACKAGE_CONTACT "RayCache developers <raycache@localhost>")
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
# Depends (Qt, Embree, libcrypto, libstdc++) are found by dpkg-shlibdeps on the executables
# alone, at packaging time (package_depends.cmake): CPack's own SHLIBDEPS runs `file` on every
# installed file to find them, thousands of processes for the docs site
set(_raycache_binaries "")
foreach(_target raycache raycache-gui)
  if(TARGET ${_target})
    string(APPEND _raycache_binaries "$<TARGET_FILE:${_target}>\n")
  endif()
endforeach()
file(GENERATE OUTPUT ${CMAKE_BINARY_DIR}/package_binaries.txt CONTENT "${_raycache_binaries}")
set(CPACK_RAYCACHE_BINARIES_FILE ${CMAKE_BINARY_DIR}/package_binaries.txt)
set(CPACK_PROJECT_CONFIG_FILE ${CMAKE_SOURCE_DIR}/cmake/package_depends.cmake)
set(CPACK_GENERATOR DEB)
include(CPack)
