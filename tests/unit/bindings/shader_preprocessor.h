#pragma once
// A small C-style preprocessor for reading shader interfaces (not for compiling them): comments
// stripped, object-like macros expanded, conditionals evaluated (defined(), !, &&, ||, integers),
// quoted #include resolved. Function-like macros count as defined but are not expanded.
#include <map>
#include <string>
#include <vector>

#include "shader_declarations.h"

namespace caustics::test {

struct PreprocessedShader {
    std::string text;                    // active lines only, macros expanded
    std::vector<std::string> problems;   // missing includes, unreadable #if expressions
};

PreprocessedShader preprocessShader(const std::string& source, const std::map<std::string, std::string>& predefined,
                                    const std::vector<std::string>& includeDirs, const IncludeReader& read);

}  // namespace caustics::test
