# Warnings for the project's own targets (not for third-party headers).
function(caustics_warnings target)
  if(MSVC)
    target_compile_options(${target} PRIVATE /W4 /permissive-)
  else()
    target_compile_options(${target} PRIVATE -Wall -Wextra -Wno-missing-field-initializers -Wno-unused-parameter)
  endif()
endfunction()

# One library per folder: every .cpp directly in the listed directories (globbed so a new file is
# picked up on the next build).
function(caustics_glob_sources out)
  set(all "")
  foreach(dir ${ARGN})
    file(GLOB found CONFIGURE_DEPENDS "${dir}/*.cpp")
    list(APPEND all ${found})
  endforeach()
  set(${out} ${all} PARENT_SCOPE)
endfunction()
