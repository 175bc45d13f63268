# Toolchain: Windows x86-64 with Debian's MinGW-w64 (g++-mingw-w64-x86-64-posix; the posix thread
# model gives std::thread/std::mutex). This is the CI check that the D3D12 backend, the passes and the
# sample's non-window code compile for Windows; users build with MSVC (preset windows-msvc). See
# docs/d3d12.md and scripts/windows-cross-check.sh.
set(CMAKE_SYSTEM_NAME Windows)
set(CMAKE_SYSTEM_PROCESSOR x86_64)
set(CMAKE_C_COMPILER x86_64-w64-mingw32-gcc-posix)
set(CMAKE_CXX_COMPILER x86_64-w64-mingw32-g++-posix)
set(CMAKE_RC_COMPILER x86_64-w64-mingw32-windres)

# Libraries and headers come from the MinGW sysroot only; programs (glslangValidator) from the host.
set(CMAKE_FIND_ROOT_PATH /usr/x86_64-w64-mingw32)
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)

# The header-only dependencies (DirectX-Headers, Vulkan, glm, tinygltf, ...) are Debian's, but they live
# in /usr/include next to Linux system headers that must never reach a Windows compile; this file,
# run right after project(), links each one into a private folder of the build and points the
# project's find_* results at it.
set(CMAKE_PROJECT_caustics_INCLUDE "${CMAKE_CURRENT_LIST_DIR}/WindowsCrossDependencies.cmake")
