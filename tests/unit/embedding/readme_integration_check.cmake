# The README's integration block is the tested code (its line count must be real). Checks that the
# ```cpp block under "## Embedding it in an engine" in README.md is the text of
# tests/gpu/embedding/host_engine.cpp between its "---- The host integration" and "---- end of the
# host integration" marker lines (compiled into embedding_gpu_tests and run by HostEngine.*), and that
# the README states that text's count of non-blank, non-comment lines.
#   cmake -DREADME=... -DSOURCE=... -P readme_integration_check.cmake
# Whole strings, never CMake lists: C++ lines hold semicolons.
file(READ "${README}" readme)
file(READ "${SOURCE}" source)

string(FIND "${readme}" "## Embedding it in an engine" section)
if(section EQUAL -1)
    message(FATAL_ERROR "README.md has no '## Embedding it in an engine' section")
endif()
string(SUBSTRING "${readme}" ${section} -1 readme)
string(FIND "${readme}" "```cpp\n" open)
string(SUBSTRING "${readme}" 0 ${open} intro)
math(EXPR open "${open} + 7")
string(SUBSTRING "${readme}" ${open} -1 rest)
string(FIND "${rest}" "\n```" close)
math(EXPR close "${close} + 1")
string(SUBSTRING "${rest}" 0 ${close} block)
if(NOT intro MATCHES "\\(([0-9]+) non-blank, non-comment lines")
    message(FATAL_ERROR "README.md's integration paragraph states no '(N non-blank, non-comment lines'")
endif()
set(stated "${CMAKE_MATCH_1}")

string(FIND "${source}" "---- The host integration" begin)
string(FIND "${source}" "// ---- end of the host integration" end)
if(begin EQUAL -1 OR end EQUAL -1)
    message(FATAL_ERROR "${SOURCE} lacks the host integration markers")
endif()
string(SUBSTRING "${source}" ${begin} -1 tail)
string(FIND "${tail}" "\n" eol)
math(EXPR begin "${begin} + ${eol} + 1")
math(EXPR length "${end} - ${begin}")
string(SUBSTRING "${source}" ${begin} ${length} code)

if(NOT block STREQUAL code)
    file(WRITE "${CMAKE_CURRENT_BINARY_DIR}/readme_block.txt" "${block}")
    file(WRITE "${CMAKE_CURRENT_BINARY_DIR}/tested_section.txt" "${code}")
    message(FATAL_ERROR "README.md's integration block is not host_engine.cpp's tested section "
                        "(diff readme_block.txt tested_section.txt in ${CMAKE_CURRENT_BINARY_DIR})")
endif()

# Non-blank, non-comment lines: drop those, then count the newlines left.
string(REGEX REPLACE "(^|\n)[ ]*(//[^\n]*)?(\n[ ]*(//[^\n]*)?)*\n" "\\1" kept "\n${code}")
string(REGEX REPLACE "[^\n]" "" newlines "${kept}")
string(LENGTH "${newlines}" count)
if(NOT stated STREQUAL "${count}")
    message(FATAL_ERROR "README.md states ${stated} lines; the tested integration has ${count}")
endif()
message(STATUS "[ measured ] README integration block = host_engine.cpp's tested section: ${count} non-blank, non-comment lines")
