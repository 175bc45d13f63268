# Run by CTest (tests/package/CMakeLists.txt). Fails with a message naming the step.
cmake_minimum_required(VERSION 3.25)
file(REMOVE_RECURSE "${WORK_DIR}")
set(staging "${WORK_DIR}/staging")
set(prefix "${WORK_DIR}/moved/prefix")

function(run step)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "package test: ${step} failed (${rc}):\n${out}\n${err}")
  endif()
  message(STATUS "package test: ${step}: ok")
endfunction()

# 1. Install, then move the prefix: a relocatable package works from wherever it lands.
run("install" ${CMAKE_COMMAND} --install "${BUILD_DIR}" --prefix "${staging}")
file(MAKE_DIRECTORY "${WORK_DIR}/moved")
file(RENAME "${staging}" "${prefix}")

# 2. Nothing of the build machine in the exported targets, nothing stray installed.
file(GLOB targetFiles "${prefix}/lib*/cmake/caustics/causticsTargets*.cmake")
if(NOT targetFiles)
  message(FATAL_ERROR "package test: no causticsTargets*.cmake under ${prefix}")
endif()
foreach(f ${targetFiles})
  file(READ "${f}" text)
  foreach(forbidden "${BUILD_DIR}" "${SOURCE_DIR}" "${staging}")
    string(FIND "${text}" "${forbidden}" at)
    if(NOT at EQUAL -1)
      message(FATAL_ERROR "package test: ${f} holds the build-machine path ${forbidden}")
    endif()
  endforeach()
  # System libraries and headers by absolute path (/usr/lib/x86_64-linux-gnu/libstb.so, /usr/include)
  # tie the package to the build machine's layout: they belong in imported targets that
  # causticsConfig.cmake finds on the consumer's machine.
  # (A path starts a quoted string or a list element; ${_IMPORT_PREFIX}/lib/... is the package's own.)
  string(REGEX MATCH "[\";]/(usr/(local/)?)?(lib[0-9]*|include)(/[^;\"]*)?" absolute "${text}")
  if(absolute)
    message(FATAL_ERROR "package test: ${f} holds the absolute system path ${absolute}")
  endif()
endforeach()
file(GLOB_RECURSE installed RELATIVE "${prefix}" "${prefix}/*")
foreach(f ${installed})
  if(f MATCHES "^bin/" OR f MATCHES "(^|/)\\.[^/]*$")
    message(FATAL_ERROR "package test: stray file installed: ${f} (no executables or marker files belong in the package)")
  endif()
endforeach()

# 3. A consumer that links only caustics::passes configures, builds and runs (lavapipe).
set(consumerBuild "${WORK_DIR}/consumer-build")
set(launcher "")
if(COMPILER_LAUNCHER)
  set(launcher "-DCMAKE_CXX_COMPILER_LAUNCHER=${COMPILER_LAUNCHER}")
endif()
run("configure consumer" ${CMAKE_COMMAND} -S "${CONSUMER_DIR}" -B "${consumerBuild}" -G "${GENERATOR}"
    "-DCMAKE_PREFIX_PATH=${prefix}" "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}" ${launcher} -DCMAKE_BUILD_TYPE=Release)
run("build consumer" ${CMAKE_COMMAND} --build "${consumerBuild}")
run("run consumer" "${consumerBuild}/caustics_consumer")

# 4. A Vulkan-only consumer: the same program with CAUSTICS_VULKAN_ONLY on its target links nothing of
# the D3D12 backend (no caustics_rhi_d3d12, no DirectX-Guids on its link line), and runs.
set(vulkanBuild "${WORK_DIR}/vulkan-consumer-build")
run("configure Vulkan-only consumer" ${CMAKE_COMMAND} -S "${CONSUMER_DIR}" -B "${vulkanBuild}" -G "${GENERATOR}"
    "-DCMAKE_PREFIX_PATH=${prefix}" "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}" ${launcher} -DCMAKE_BUILD_TYPE=Release
    -DCAUSTICS_CONSUMER_VULKAN_ONLY=ON)
execute_process(COMMAND ${CMAKE_COMMAND} --build "${vulkanBuild}" --verbose
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "package test: build Vulkan-only consumer failed (${rc}):\n${out}\n${err}")
endif()
foreach(d3d12Part "caustics_rhi_d3d12" "DirectX-Guids")
  string(FIND "${out}" "${d3d12Part}" at)
  if(NOT at EQUAL -1)
    message(FATAL_ERROR "package test: the Vulkan-only consumer links ${d3d12Part}:\n${out}")
  endif()
endforeach()
message(STATUS "package test: build Vulkan-only consumer (no D3D12 on its link line): ok")
run("run Vulkan-only consumer" "${vulkanBuild}/caustics_consumer")
