// Checks on the raw glTF JSON before tinygltf parses it, where tinygltf's own errors would mislead
// ("asset object not found" for glTF 1.0, "accessor[0] invalid bufferView" for Draco, a whole data
// URI echoed for a wrong byteLength, "must be the multiple of 4" for a byteStride of 2^30) or where it
// would open files outside the asset root (gltf_uris.cpp). Anything these checks cannot read is left to
// tinygltf.
#include <cctype>
#include <cstdio>
#include <cstring>
#include <optional>
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
    if (version != asset->end() && version->is_number())   // glTF 1.0 exporters wrote `"version": 1`
        return makeError("asset.version is the number " + version->dump() + ", not a string: a glTF " + version->dump() +
                         " file? Only glTF 2.0 (asset.version \"2.0\") is supported: convert it, e.g. by importing "
                         "and re-exporting it in Blender");
    if (version == asset->end()) return makeError("asset.version is missing; glTF 2.0 requires \"2.0\"");
    if (!version->is_string())
        return makeError("asset.version is " + std::string(version->type_name()) + ", not a string; glTF 2.0 requires \"2.0\"");
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

// Top-level fields glTF 2.0 defines as arrays, and the per-mesh primitives: tinygltf skips a field of the
// wrong type silently, which ends in "contains no meshes" or "no triangle primitives" for a file that has them.
Status checkArrays(const Json& root) {
    static const char* const kArrays[] = {"accessors", "animations", "buffers",  "bufferViews", "cameras",
                                          "images",    "materials",  "meshes",   "nodes",       "samplers",
                                          "scenes",    "skins",      "textures", "extensionsUsed", "extensionsRequired"};
    for (const char* key : kArrays) {
        auto it = root.find(key);
        if (it != root.end() && !it->is_array())
            return makeError("\"" + std::string(key) + "\" is " + std::string(it->type_name()) + ", not an array (glTF 2.0 5.x)");
    }
    auto meshes = root.find("meshes");
    if (meshes == root.end()) return okStatus();
    for (size_t m = 0; m < meshes->size(); ++m) {
        const Json& mesh = (*meshes)[m];
        std::string where = "meshes[" + std::to_string(m) + "]";
        if (!mesh.is_object()) return makeError(where + " is " + std::string(mesh.type_name()) + ", not an object");
        auto prims = mesh.find("primitives");
        if (prims == mesh.end()) return makeError(where + ".primitives is missing (glTF 2.0 requires it)");
        if (!prims->is_array())
            return makeError(where + ".primitives is " + std::string(prims->type_name()) + ", not an array of primitives");
    }
    return okStatus();
}

// bufferView.byteStride: glTF 2.0 schema minimum 4, maximum 252, a multiple of 4.
Status checkStrides(const Json& root) {
    auto views = root.find("bufferViews");
    if (views == root.end()) return okStatus();
    for (size_t i = 0; i < views->size(); ++i) {
        const Json& v = (*views)[i];
        if (!v.is_object()) continue;
        auto stride = v.find("byteStride");
        if (stride == v.end()) continue;
        bool whole = stride->is_number_unsigned() || stride->is_number_integer();
        long long s = whole ? stride->get<long long>() : 0;
        if (!whole || s < 4 || s > 252 || s % 4 != 0)
            return makeError("bufferViews[" + std::to_string(i) + "].byteStride is " + shortened(stride->dump(), 32) +
                             "; glTF 2.0 allows a multiple of 4 from 4 to 252");
    }
    return okStatus();
}

// tinygltf decodes only these data URIs; any other "data:" URI it would take for a file name.
bool knownDataUri(const std::string& uri) {
    static const char* const kPrefixes[] = {"data:application/octet-stream;base64,", "data:application/gltf-buffer;base64,",
                                            "data:image/jpeg;base64,", "data:image/png;base64,", "data:image/bmp;base64,",
                                            "data:image/gif;base64,", "data:text/plain;base64,"};
    for (const char* p : kPrefixes)
        if (uri.rfind(p, 0) == 0) return true;
    return false;
}

// The base64 alphabet (RFC 4648 4) with at most two '=' at the end; the offset of the first bad character.
std::optional<size_t> badBase64(const std::string& payload) {
    size_t end = payload.size();
    for (int pad = 0; pad < 2 && end > 0 && payload[end - 1] == '='; ++pad) --end;
    for (size_t i = 0; i < end; ++i) {
        char c = payload[i];
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '+' || c == '/')) return i;
    }
    return std::nullopt;
}

std::string printable(char c) {
    if (c >= 0x20 && c < 0x7f) return std::string("'") + c + "'";
    char code[8];
    std::snprintf(code, sizeof(code), "0x%02x", unsigned(static_cast<unsigned char>(c)));
    return code;
}

// A data URI: a media type tinygltf decodes and a valid base64 payload.
Status checkDataUri(const std::string& field, const std::string& uri) {
    size_t comma = uri.find(";base64,");
    if (comma == std::string::npos) return makeError(field + " is a data URI that is not base64 (" + shortened(uri, 48) + ")");
    if (!knownDataUri(uri))
        return makeError(field + " is a data URI of media type '" + shortened(uri.substr(5, comma - 5), 48) +
                         "'; supported: application/octet-stream, application/gltf-buffer, image/png, image/jpeg, "
                         "image/bmp, image/gif");
    std::string payload = uri.substr(comma + 8);
    if (auto bad = badBase64(payload))
        return makeError(field + ": the data URI's base64 payload has the invalid character " + printable(payload[*bad]) +
                         " at offset " + std::to_string(*bad) + " (base64 uses A-Z a-z 0-9 + / and '=' padding)");
    return okStatus();
}

// Every external (non-data) URI of images and buffers: inside the asset root, a regular file.
Status checkExternalUris(const Json& root, const AssetRoot& assets) {
    for (const char* key : {"buffers", "images"}) {
        auto list = root.find(key);
        if (list == root.end()) continue;
        for (size_t i = 0; i < list->size(); ++i) {
            const Json& item = (*list)[i];
            if (!item.is_object()) continue;
            auto uri = item.find("uri");
            if (uri == item.end() || !uri->is_string()) continue;
            std::string field = std::string(key) + "[" + std::to_string(i) + "].uri";
            const std::string& text = uri->get_ref<const std::string&>();
            if (text.rfind("data:", 0) == 0) CAUSTICS_CHECK(checkDataUri(field, text));
            else CAUSTICS_CHECK(checkUri(assets, field, text, std::string(key) == "images"));
        }
    }
    return okStatus();
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

// Perspective cameras (glTF 2.0 5.13): aspectRatio > 0 when given, zfar > znear when given. tinygltf
// reads an absent aspectRatio as 0, so only the raw JSON tells a written 0 from none.
void checkCameras(const Json& root, std::vector<std::string>& warnings) {
    auto cameras = root.find("cameras");
    if (cameras == root.end()) return;
    for (size_t i = 0; i < cameras->size(); ++i) {
        const Json& c = (*cameras)[i];
        if (!c.is_object()) continue;
        auto p = c.find("perspective");
        if (p == c.end() || !p->is_object()) continue;
        std::string where = "cameras[" + std::to_string(i) + "].perspective.";
        auto aspect = p->find("aspectRatio");
        if (aspect != p->end() && !(aspect->is_number() && aspect->get<double>() > 0.0))
            warnings.push_back(where + "aspectRatio is " + shortened(aspect->dump(), 32) +
                               "; glTF 2.0 requires a number above 0: the camera uses the image's aspect ratio");
        auto znear = p->find("znear"), zfar = p->find("zfar");
        if (znear != p->end() && !(znear->is_number() && znear->get<double>() > 0.0))
            warnings.push_back(where + "znear is " + shortened(znear->dump(), 32) +
                               "; glTF 2.0 requires a number above 0: using the default near plane 0.05 m");
        if (znear != p->end() && zfar != p->end() && znear->is_number() && zfar->is_number() &&
            !(zfar->get<double>() > znear->get<double>()))
            warnings.push_back(where + "zfar " + shortened(zfar->dump(), 32) + " is not above znear " +
                               shortened(znear->dump(), 32) + " (glTF 2.0 requires zfar > znear): zfar is ignored, the far plane comes from the scene's bounds");
    }
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

Status preflightJson(const unsigned char* json, size_t size, const AssetRoot& assets, std::vector<std::string>& warnings) {
    Json root = Json::parse(json, json + size, nullptr, /*allow_exceptions=*/false);
    if (root.is_discarded() || !root.is_object()) return okStatus();   // tinygltf reports the syntax error
    CAUSTICS_CHECK(checkVersion(root));
    CAUSTICS_CHECK(checkArrays(root));
    CAUSTICS_CHECK(checkRequiredExtensions(root));
    CAUSTICS_CHECK(checkStrides(root));
    CAUSTICS_CHECK(checkExternalUris(root, assets));
    CAUSTICS_CHECK(checkBufferLengths(root));
    checkCameras(root, warnings);
    return okStatus();
}

}  // namespace caustics::scene::gltf
