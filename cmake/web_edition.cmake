# The web edition built beside the native build, in web-edition/ (the web preset's
# configuration, through Emscripten's CMake toolchain), when Emscripten is installed
# (scripts/setup.sh --with-web): the browser test (tests/web) and the docs' live figures
# (docs/) use it, so it is built once, here. Defines the target raycache_web_edition and
# RAYCACHE_WEB_DIR, the folder of its page.
find_program(RAYCACHE_EMCMAKE emcmake)
find_file(RAYCACHE_EMSCRIPTEN_TOOLCHAIN Emscripten.cmake
  PATHS /usr/share/emscripten/cmake/Modules/Platform /usr/lib/emscripten/cmake/Modules/Platform NO_DEFAULT_PATH)
if(NOT RAYCACHE_EMCMAKE OR NOT RAYCACHE_EMSCRIPTEN_TOOLCHAIN)
  message(STATUS "Emscripten not found (scripts/setup.sh --with-web): no web edition, "
                 "the docs show static pictures")
  return()
endif()
include(ExternalProject)
ExternalProject_Add(raycache_web_edition
  SOURCE_DIR ${CMAKE_SOURCE_DIR}
  BINARY_DIR ${CMAKE_BINARY_DIR}/web-edition
  CMAKE_GENERATOR Ninja
  CMAKE_ARGS -DCMAKE_TOOLCHAIN_FILE=${RAYCACHE_EMSCRIPTEN_TOOLCHAIN} -DCMAKE_BUILD_TYPE=Release
             -DRAYCACHE_SCENES_DIR=${RAYCACHE_SCENES_DIR}
  BUILD_COMMAND ${CMAKE_COMMAND} --build <BINARY_DIR> --target raycache_web raycache_web_toy
  BUILD_ALWAYS ON
  INSTALL_COMMAND ""
  USES_TERMINAL_BUILD ON)
set(RAYCACHE_WEB_DIR ${CMAKE_BINARY_DIR}/web-edition/web)
