// Checks on the raw glTF JSON before tinygltf parses it, where tinygltf's own errors would mislead
// ("asset object not found" for glTF 1.0, "accessor[0] invalid bufferView" for Draco, a whole data
// URI echoed for a wrong byteLength). Anything these checks cannot read is left to tinygltf.
#include <cstring>
#include <set>

#include <nlohmann/json.hpp>

#include "gltf_internal.h"

namespace caustics::scene::gltf {
namespace {

using Json = nlohmann::json;

// Extensions whose absence of support would change the result; anything else in
// extensionsRequired is refused (glTF 2.0 3.12).
const std::set<std::string> kSupportedExtensions = {
    "KHR_materials_transmission", "KHR_materials_ior",  "KHR_materials_volume",
    "KHR_materials_specular",     "KHR_lights_punctual", "KHR_materials_emissive_strength",
};

Status checkVersion(const Json& root) {
    auto asset = root.find("asset");
    if (asset == root.end() || !asset->is_object()) {
        // glTF 1.0 made "asset" optional and keyed meshes, nodes, ... by id in objects (2.0: arrays).
        auto meshes = root.find("meshes");
        if (meshes != root.end() && meshes->is_object())
            return makeError("is a glTF 1.0 file (\"meshes\" is an object keyed by id and there is no \"asset\"); "
                             "only glTF 2.0 is supported: convert it, e.g. by importing and re-exporting it in Blender");
        return makeError("has no \"asset\" object, which glTF 2.0 requires (asset.version = \"2.0\")");
    }
    auto version = asset->find("version");
    if (version == asset->end() || !version->is_string())
        return makeError("asset.version is missing or not a string; glTF 2.0 requires \"2.0\"");
    std::string v = version->get<std::string>();
    if (v.rfind("2.", 0) != 0)
        return makeError("is a glTF " + shortened(v, 16) + " file (asset.version); only glTF 2.0 is supported: "
                         "convert it, e.g. by importing and re-exporting it in Blender");
    return okStatus();
}

Status checkRequiredExtensions(const Json& root) {
    auto required = root.find("extensionsRequired");
    if (required == root.end() || !required->is_array()) return okStatus();
    for (const Json& ext : *required) {
        if (!ext.is_string()) continue;
        std::string name = ext.get<std::string>();
        if (kSupportedExtensions.count(name)) continue;
        std::string hint = name == "KHR_draco_mesh_compression"
                               ? " (Draco-compressed meshes: decompress them first, e.g. `gltf-transform copy in.glb out.glb`)"
                               : "";
        return makeError("requires the unsupported extension '" + shortened(name, 64) + "' (extensionsRequired)" + hint);
    }
    return okStatus();
}

// Length of what a base64 payload decodes to (padding '=' excluded); tinygltf refuses a data URI
// whose decoded length differs from the buffer's byteLength, and its error echoes the whole URI.
size_t base64DecodedLength(const std::string& payload) {
    size_t n = payload.size();
    size_t padding = 0;
    while (padding < 2 && n > padding && payload[n - 1 - padding] == '=') ++padding;
    return (n / 4) * 3 + (n % 4 ? (n % 4) - 1 : 0) - (n % 4 ? 0 : padding);
}

Status checkBufferLengths(const Json& root) {
    auto buffers = root.find("buffers");
    if (buffers == root.end() || !buffers->is_array()) return okStatus();
    for (size_t i = 0; i < buffers->size(); ++i) {
        const Json& b = (*buffers)[i];
        if (!b.is_object()) continue;
        std::string where = "buffers[" + std::to_string(i) + "]";
        auto length = b.find("byteLength");
        if (length == b.end() || !length->is_number_unsigned() || length->get<uint64_t>() == 0)
            return makeError(where + ".byteLength is missing or not a positive whole number");
        auto uri = b.find("uri");
        if (uri == b.end() || !uri->is_string()) continue;
        const std::string& text = uri->get_ref<const std::string&>();
        if (text.rfind("data:", 0) != 0) continue;
        size_t comma = text.find(";base64,");
        if (comma == std::string::npos) return makeError(where + ".uri is a data URI that is not base64 (" + shortened(text, 48) + ")");
        size_t decoded = base64DecodedLength(text.substr(comma + 8));
        uint64_t declared = length->get<uint64_t>();
        if (decoded != declared)
            return makeError(where + ".byteLength is " + std::to_string(declared) + ", but its data URI holds " +
                             std::to_string(decoded) + " bytes");
    }
    return okStatus();
}

}  // namespace

bool isSupportedExtension(const std::string& name) { return kSupportedExtensions.count(name) != 0; }

std::string shortened(const std::string& text, size_t maxChars) {
    if (text.size() <= maxChars) return text;
    return text.substr(0, maxChars) + "... (" + std::to_string(text.size()) + " characters)";
}

std::string shortenLongWords(const std::string& text, size_t maxWord) {
    std::string out;
    size_t i = 0;
    while (i < text.size()) {
        size_t end = text.find_first_of(" \n", i);
        if (end == std::string::npos) end = text.size();
        out += shortened(text.substr(i, end - i), maxWord);
        if (end < text.size()) out += text[end];
        i = end + 1;
    }
    return out;
}

Status preflightGlb(const std::vector<unsigned char>& bytes) {
    if (bytes.size() < 12) return makeError("is too short for a binary glTF header (12 bytes)");
    uint32_t version = 0;
    std::memcpy(&version, bytes.data() + 4, 4);
    if (version != 2)
        return makeError("is a binary glTF version " + std::to_string(version) +
                         " file (GLB header); only version 2 (glTF 2.0) is supported");
    return okStatus();
}

Status preflightJson(const unsigned char* json, size_t size) {
    Json root = Json::parse(json, json + size, nullptr, /*allow_exceptions=*/false);
    if (root.is_discarded() || !root.is_object()) return okStatus();   // tinygltf reports the syntax error
    CAUSTICS_CHECK(checkVersion(root));
    CAUSTICS_CHECK(checkRequiredExtensions(root));
    CAUSTICS_CHECK(checkBufferLengths(root));
    return okStatus();
}

}  // namespace caustics::scene::gltf
