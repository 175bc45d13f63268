#include "output_paths.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace caustics::sample {

namespace fs = std::filesystem;

Status checkWritable(const std::string& option, const std::string& path) {
    if (path.empty()) return makeError(option + ": the path is empty");
    std::error_code ec;
    fs::path p(path);
    if (fs::is_directory(p, ec)) return makeError(option + ": '" + path + "' is a directory");
    if (fs::path parent = p.parent_path(); !parent.empty() && !fs::exists(parent, ec)) {
        fs::create_directories(parent, ec);
        if (ec) return makeError(option + ": cannot create the folder '" + parent.string() + "': " + ec.message());
    }
    bool existed = fs::exists(p, ec);
    {
        std::ofstream probe(path, std::ios::app | std::ios::binary);   // append: an existing file is kept intact
        if (!probe) return makeError(option + ": cannot write '" + path + "': " + std::strerror(errno));
    }
    if (!existed) fs::remove(p, ec);
    return okStatus();
}

Status writeTextFile(const std::string& option, const std::string& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    if (!out) return makeError(option + ": cannot write '" + path + "': " + std::strerror(errno));
    out << text;
    out.flush();
    if (!out) return makeError(option + ": writing '" + path + "' failed (disk full?)");
    return okStatus();
}

}  // namespace caustics::sample
