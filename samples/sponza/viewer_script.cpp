#include "viewer_script.h"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>

namespace caustics::sample {
namespace {

struct Arity {
    size_t min, max;   // argument words after the command
};

const std::map<std::string, Arity>& commandArity() {
    static const std::map<std::string, Arity> table = {
        {"set", {2, 2}},        {"key", {1, 1}},     {"screenshot", {1, 1}}, {"camera", {1, 7}},
        {"light", {3, 5}},      {"ui", {1, 1}},      {"resize", {2, 2}},     {"animate", {2, 3}},
        {"quit", {0, 0}},
    };
    return table;
}

}  // namespace

Result<Script> parseScript(const std::string& text, const std::string& fileName) {
    Script script;
    std::istringstream lines(text);
    std::string line;
    for (uint32_t number = 1; std::getline(lines, line); ++number) {
        if (!line.empty() && line.back() == '\r') line.pop_back();   // CRLF files
        // A control byte (a NUL above all) would cut every message that quotes the line: name it instead.
        for (size_t col = 0; col < line.size(); ++col) {
            unsigned char ch = static_cast<unsigned char>(line[col]);
            if ((ch < 0x20 && ch != '\t') || ch == 0x7f) {
                char code[8];
                std::snprintf(code, sizeof(code), "0x%02x", unsigned(ch));
                return makeError(fileName + ":" + std::to_string(number) + ": control byte " + code + (ch == 0 ? " (NUL)" : "") +
                                 " at column " + std::to_string(col + 1) + "; a script is plain text");
            }
        }
        if (auto hash = line.find('#'); hash != std::string::npos) line.resize(hash);
        std::istringstream words(line);
        std::vector<std::string> w;
        for (std::string word; words >> word;) w.push_back(word);
        if (w.empty()) continue;
        std::string where = fileName + ":" + std::to_string(number);
        ScriptCommand c;
        auto [end, ec] = std::from_chars(w[0].data(), w[0].data() + w[0].size(), c.frame);
        if (ec != std::errc() || end != w[0].data() + w[0].size())
            return makeError(where + ": expected '<frame> <command> ...', and '" + w[0] + "' is not a frame number");
        if (w.size() < 2) return makeError(where + ": frame " + w[0] + " has no command");
        auto arity = commandArity().find(w[1]);
        if (arity == commandArity().end()) {
            std::string known;
            for (const auto& [name, a] : commandArity()) known += (known.empty() ? "" : ", ") + name;
            return makeError(where + ": unknown command '" + w[1] + "' (one of " + known + ")");
        }
        size_t args = w.size() - 2;
        if (args < arity->second.min || args > arity->second.max)
            return makeError(where + ": '" + w[1] + "' takes " + std::to_string(arity->second.min) +
                             (arity->second.max != arity->second.min ? " to " + std::to_string(arity->second.max) : "") +
                             " arguments, got " + std::to_string(args));
        c.words.assign(w.begin() + 1, w.end());
        c.where = where;
        script.commands.push_back(std::move(c));
    }
    std::stable_sort(script.commands.begin(), script.commands.end(),
                     [](const ScriptCommand& a, const ScriptCommand& b) { return a.frame < b.frame; });
    return script;
}

Result<Script> loadScript(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return makeError("--script: cannot read '" + path + "'");
    std::stringstream text;
    text << in.rdbuf();
    return parseScript(text.str(), path);
}

}  // namespace caustics::sample
