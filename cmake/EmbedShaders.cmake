# caustics_embed_shaders(<target> NAMESPACE <ns> BASE_DIR <dir> SOURCES <files...> [INCLUDE_DIRS <dirs...>]
#                        [PASS_DIR <dir> PASS_SOURCES <files...>] [DEPENDS <files...>])
# Compiles GLSL to SPIR-V with glslangValidator at build time (a compile error fails the build with the
# file and line) and embeds the SPIR-V in <target> through a generated source file. The shaders are
# looked up at run time by their path relative to BASE_DIR:  <ns>::spirv("forward/trace.rgen"); a
# pass's own shaders, PASS_DIR/<pass>/shaders/<file>, by "<pass>/<file>" (docs/shaders.md). DEPENDS:
# what every compile waits for (the generated binding declarations).
find_program(GLSLANG_VALIDATOR glslangValidator REQUIRED)

function(caustics_embed_shaders target)
  cmake_parse_arguments(ARG "" "NAMESPACE;BASE_DIR;PASS_DIR" "SOURCES;INCLUDE_DIRS;PASS_SOURCES;DEPENDS" ${ARGN})
  set(outDir "${CMAKE_CURRENT_BINARY_DIR}/${target}_spirv")
  set(includeFlags "")
  foreach(dir ${ARG_INCLUDE_DIRS})
    list(APPEND includeFlags "-I${dir}")
  endforeach()
  set(spvFiles "")
  set(names "")
  foreach(src ${ARG_SOURCES} ${ARG_PASS_SOURCES})
    get_filename_component(abs "${src}" ABSOLUTE)
    if(ARG_PASS_DIR AND abs MATCHES "^${ARG_PASS_DIR}/([^/]+)/shaders/([^/]+)$")
      set(rel "${CMAKE_MATCH_1}/${CMAKE_MATCH_2}")
    else()
      file(RELATIVE_PATH rel "${ARG_BASE_DIR}" "${abs}")
    endif()
    set(spv "${outDir}/${rel}.spv")
    get_filename_component(spvDir "${spv}" DIRECTORY)
    add_custom_command(
      OUTPUT "${spv}"
      COMMAND ${CMAKE_COMMAND} -E make_directory "${spvDir}"
      COMMAND ${GLSLANG_VALIDATOR} -V --target-env vulkan1.2 -g0 ${includeFlags} --depfile "${spv}.d" -o "${spv}" "${abs}"
      DEPENDS "${abs}" ${ARG_DEPENDS}
      DEPFILE "${spv}.d"
      COMMENT "glslang ${rel}"
      VERBATIM)
    list(APPEND spvFiles "${spv}")
    list(APPEND names "${rel}")
  endforeach()
  set(genCpp "${outDir}/${target}_embedded_shaders.cpp")
  add_custom_command(
    OUTPUT "${genCpp}"
    COMMAND ${CMAKE_COMMAND} -DOUT=${genCpp} -DNAMESPACE=${ARG_NAMESPACE} -DSPV_DIR=${outDir}
            "-DNAMES=${names}" -P "${CAUSTICS_CMAKE_DIR}/GenerateShaderTable.cmake"
    DEPENDS ${spvFiles} "${CAUSTICS_CMAKE_DIR}/GenerateShaderTable.cmake"
    COMMENT "Embedding SPIR-V into ${target}"
    VERBATIM)
  target_sources(${target} PRIVATE "${genCpp}")
endfunction()
