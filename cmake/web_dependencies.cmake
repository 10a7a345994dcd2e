# The web edition's header-only dependencies. em++ must never see -I/usr/include (glibc's
# headers would shadow Emscripten's libc), so each library's own folder is linked into
# a folder of the build that holds nothing else, and that folder is the include path.
set(RAYCACHE_WEB_INCLUDE ${CMAKE_BINARY_DIR}/web-include)
file(MAKE_DIRECTORY ${RAYCACHE_WEB_INCLUDE})
set(RAYCACHE_HOST_INCLUDE /usr/include CACHE PATH "Where the host's GLM, nlohmann-json, stb and CLI11 headers are")
foreach(dir glm nlohmann stb CLI)
  if(NOT EXISTS ${RAYCACHE_HOST_INCLUDE}/${dir})
    message(FATAL_ERROR "web edition: ${RAYCACHE_HOST_INCLUDE}/${dir} not found (scripts/setup.sh installs it)")
  endif()
  file(CREATE_LINK ${RAYCACHE_HOST_INCLUDE}/${dir} ${RAYCACHE_WEB_INCLUDE}/${dir} SYMBOLIC)
endforeach()
add_library(glm::glm INTERFACE IMPORTED)
target_include_directories(glm::glm SYSTEM INTERFACE ${RAYCACHE_WEB_INCLUDE})
add_library(nlohmann_json::nlohmann_json INTERFACE IMPORTED)
target_include_directories(nlohmann_json::nlohmann_json SYSTEM INTERFACE ${RAYCACHE_WEB_INCLUDE})
set(STB_INCLUDE_DIR ${RAYCACHE_WEB_INCLUDE})
add_library(CLI11::CLI11 INTERFACE IMPORTED)
target_include_directories(CLI11::CLI11 SYSTEM INTERFACE ${RAYCACHE_WEB_INCLUDE})
# The acorn parser Emscripten's linker runs under Node is a Debian package in
# /usr/share/nodejs, where a Node from elsewhere does not look
set(CMAKE_CXX_LINKER_LAUNCHER ${CMAKE_COMMAND} -E env NODE_PATH=/usr/share/nodejs)
