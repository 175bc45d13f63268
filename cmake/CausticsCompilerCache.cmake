# Uses ccache when it is installed and no launcher was chosen, for every build folder (build/,
# build-sanitize/, build-mingw/): CI rebuilds from a fresh clone each time (.ci/run). Paths are made
# relative to the checkout, so clones in other folders share the cache.
option(CAUSTICS_USE_CCACHE "Compile through ccache when it is installed" ON)
if(CAUSTICS_USE_CCACHE AND NOT CMAKE_CXX_COMPILER_LAUNCHER)
  find_program(CAUSTICS_CCACHE ccache)
  if(CAUSTICS_CCACHE)
    set(CMAKE_CXX_COMPILER_LAUNCHER
        "${CMAKE_COMMAND};-E;env;CCACHE_BASEDIR=${CMAKE_SOURCE_DIR};CCACHE_NOHASHDIR=1;${CAUSTICS_CCACHE}")
  endif()
endif()
