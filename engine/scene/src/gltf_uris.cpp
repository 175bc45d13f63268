// External glTF URIs as untrusted input (docs/viewer.md, "Untrusted glTF"): a URI names a regular file
// inside the asset root or nothing is opened. Two layers: resolveUri() gives the refusal its words (the
// preflight calls it for every buffers[i].uri and images[i].uri), and the file-system callbacks handed to
// tinygltf enforce the same rule on every path tinygltf itself tries (it also searches the working
// directory and, by default, expands `~` and environment variables).
#include <fstream>

#include "gltf_internal.h"

namespace caustics::scene::gltf {
namespace {

namespace fs = std::filesystem;

// Percent-decoding as tinygltf does it (RFC 3986 2.1; tinygltf also maps '+' to a space), so the file
// checked here is the file tinygltf would ask for.
std::string percentDecoded(const std::string& uri) {
    auto hex = [](char c) -> int {
        if (c >= '0' && c <= '9') return c - '0';
        if (c >= 'a' && c <= 'f') return c - 'a' + 10;
        if (c >= 'A' && c <= 'F') return c - 'A' + 10;
        return 0;
    };
    std::string out;
    for (size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] == '+') out += ' ';
        else if (uri[i] == '%' && i + 2 < uri.size()) {
            out += char((hex(uri[i + 1]) << 4) | hex(uri[i + 2]));
            i += 2;
        } else out += uri[i];
    }
    return out;
}

// Whether `path` (canonical) lies inside `root` (canonical): every component of root is a prefix.
bool isInside(const fs::path& path, const fs::path& root) {
    auto p = path.begin();
    for (auto r = root.begin(); r != root.end(); ++r, ++p) {
        if (r->empty()) continue;   // a trailing separator
        if (p == path.end() || *p != *r) return false;
    }
    return true;
}

std::string kindOf(const fs::file_status& status) {
    switch (status.type()) {
        case fs::file_type::directory: return "a directory";
        case fs::file_type::character: return "a character device";
        case fs::file_type::block: return "a block device";
        case fs::file_type::fifo: return "a FIFO (named pipe)";
        case fs::file_type::socket: return "a socket";
        default: return "not a regular file";
    }
}

const std::string kWiden = " (widen it with LoadOptions::assetRoot or the sample's --asset-root DIR)";

// The file `decoded` names, checked; `field` and `uri` only word the errors.
// `relativeOk`: tinygltf's own lookups join the folder and the URI into one absolute path.
// `missingOk`: a file that does not exist is no error here (a missing image becomes white, with tinygltf's
// warning).
Result<fs::path> confine(const AssetRoot& root, const std::string& field, const std::string& uri, const std::string& decoded,
                         bool relativeOk, bool missingOk = false) {
    std::string quoted = field + " '" + shortened(uri, 96) + "'";
    if (decoded.empty()) return makeError(field + " is empty");
    if (decoded.find('\0') != std::string::npos) return makeError(quoted + " contains a NUL byte");
    fs::path named(decoded);
    if (root.root.empty())
        return makeError(quoted + " names an external file, but the glTF was loaded from memory without "
                         "LoadOptions::assetRoot: no file is read");
    fs::path joined = named.is_absolute() ? named : root.modelDir / named;
    std::error_code ec;
    // weakly_canonical: symbolic links and `..` resolved, so a link inside the root that points out of
    // it is judged by where it points.
    fs::path resolved = fs::weakly_canonical(joined, ec);
    if (ec) resolved = joined.lexically_normal();
    if (!isInside(resolved, root.root))
        return makeError(quoted + " resolves to '" + shortened(resolved.string(), 160) + "', outside the asset root '" +
                         root.root.string() + "'" + kWiden);
    if (named.is_absolute() && !relativeOk)
        return makeError(quoted + " is an absolute path; glTF 2.0 (3.3) URIs are relative to the glTF file: "
                         "write it as '" + shortened(resolved.lexically_relative(root.modelDir).generic_string(), 96) + "'");
    fs::file_status status = fs::status(resolved, ec);   // stat, never open
    if (status.type() == fs::file_type::not_found && missingOk) return resolved;
    if (status.type() == fs::file_type::not_found)
        return makeError(quoted + ": file not found (looked for '" + shortened(resolved.string(), 160) + "')");
    if (status.type() != fs::file_type::regular)
        return makeError(quoted + " resolves to '" + shortened(resolved.string(), 160) + "', which is " + kindOf(status) +
                         "; only regular files are read");
    return resolved;
}

// tinygltf FsCallbacks (user_data = the AssetRoot). A path outside the root or not a regular file
// "does not exist" for tinygltf, so it is never opened.
bool confinedExists(const std::string& path, void* user) {
    const auto* root = static_cast<const AssetRoot*>(user);
    return confine(*root, "uri", path, path, true).ok();
}

std::string unexpanded(const std::string& path, void*) { return path; }   // no `~`, no $VARIABLES

bool confinedRead(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user) {
    const auto* root = static_cast<const AssetRoot*>(user);
    auto file = confine(*root, "uri", path, path, true);
    if (!file) {
        if (err) *err += file.message();
        return false;
    }
    std::ifstream in(*file, std::ios::binary);
    if (!in) {
        if (err) *err += "cannot open '" + file->string() + "'";
        return false;
    }
    out->assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    return !in.bad();
}

bool refuseWrite(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
    if (err) *err += "the importer writes no files";
    return false;
}

}  // namespace

Result<AssetRoot> makeAssetRoot(const std::string& modelDir, const std::string& assetRoot) {
    AssetRoot r;
    std::error_code ec;
    if (!modelDir.empty()) {
        r.modelDir = fs::weakly_canonical(fs::absolute(modelDir, ec), ec);
        if (ec) r.modelDir = fs::absolute(modelDir).lexically_normal();
    }
    if (assetRoot.empty()) {
        r.root = r.modelDir;   // from memory without a root: no external file at all (confine refuses)
        return r;
    }
    fs::path root = fs::absolute(assetRoot, ec);
    if (!fs::is_directory(root, ec))
        return makeError("LoadOptions::assetRoot '" + assetRoot + "' is not a directory");
    r.root = fs::canonical(root, ec);
    if (ec) return makeError("LoadOptions::assetRoot '" + assetRoot + "': " + ec.message());
    if (r.modelDir.empty()) r.modelDir = r.root;   // from memory: relative URIs resolve in the root
    return r;
}

Status checkUri(const AssetRoot& root, const std::string& field, const std::string& uri, bool missingOk) {
    auto file = confine(root, field, uri, percentDecoded(uri), false, missingOk);
    if (!file) return file.error();
    return okStatus();
}

tinygltf::FsCallbacks confinedFileSystem(const AssetRoot& root) {
    tinygltf::FsCallbacks callbacks{};
    callbacks.FileExists = confinedExists;
    callbacks.ExpandFilePath = unexpanded;
    callbacks.ReadWholeFile = confinedRead;
    callbacks.WriteWholeFile = refuseWrite;
    callbacks.user_data = const_cast<AssetRoot*>(&root);
    return callbacks;
}

}  // namespace caustics::scene::gltf
