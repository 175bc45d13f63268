# -DCAUSTICS_SANITIZE=ON: AddressSanitizer + UndefinedBehaviorSanitizer on every target of this build
# (compile and link). Use a separate build folder; scripts/sanitize-check.sh builds only the glTF fuzz
# test and the sample with it and runs them on broken files. UBSan findings abort (no recovery), so a
# finding fails the test that met it.
option(CAUSTICS_SANITIZE "Build with AddressSanitizer and UndefinedBehaviorSanitizer" OFF)
if(CAUSTICS_SANITIZE)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
    message(FATAL_ERROR "CAUSTICS_SANITIZE needs GCC or Clang (-fsanitize=address,undefined)")
  endif()
  set(causticsSanitizeFlags -fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer)
  add_compile_options(${causticsSanitizeFlags})
  add_link_options(-fsanitize=address,undefined)
endif()
