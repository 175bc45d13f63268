#pragma once
// --script FILE: per-frame commands that drive the viewer the way a user does, so CI can run it under
// Xvfb and compare screenshots. One command per line, "<frame> <command> [arguments]", '#' starts a
// comment; the commands are listed in docs/viewer.md. The file is checked completely before the
// window opens: an unknown command or a wrong argument count names the file and line.
#include <cstdint>
#include <string>
#include <vector>

#include "caustics/rhi/result.h"

namespace caustics::sample {

struct ScriptCommand {
    uint32_t frame = 0;
    std::vector<std::string> words;   // words[0] is the command
    std::string where;                // "file:line" for messages
};

struct Script {
    std::vector<ScriptCommand> commands;   // sorted by frame, file order within a frame
    uint32_t lastFrame() const { return commands.empty() ? 0 : commands.back().frame; }
};

Result<Script> parseScript(const std::string& text, const std::string& fileName);
Result<Script> loadScript(const std::string& path);

}  // namespace caustics::sample
