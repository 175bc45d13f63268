// The GLB container (glTF 2.0 section 4.4) checked before tinygltf reads it: tinygltf answers every
// inconsistency with a bare "Invalid glTF binary.", so each one is named here with the numbers involved.
#include <cstdio>
#include <cstring>

#include "gltf_internal.h"

namespace caustics::scene::gltf {
namespace {

constexpr uint32_t kJsonChunk = 0x4E4F534A;   // "JSON"
constexpr uint32_t kBinChunk = 0x004E4942;    // "BIN\0"

uint32_t word(const std::vector<unsigned char>& bytes, size_t at) {
    uint32_t v = 0;
    std::memcpy(&v, bytes.data() + at, 4);
    return v;
}

std::string hex(uint32_t v) {
    char text[16];
    std::snprintf(text, sizeof(text), "0x%08X", v);
    return text;
}

}  // namespace

Status preflightGlb(const std::vector<unsigned char>& bytes) {
    size_t size = bytes.size();
    if (size < 12) return makeError("is too short for a binary glTF header (12 bytes)");
    uint32_t version = word(bytes, 4);
    if (version != 2)
        return makeError("is a binary glTF version " + std::to_string(version) +
                         " file (GLB header); only version 2 (glTF 2.0) is supported");
    uint32_t declared = word(bytes, 8);
    if (declared > size)
        return makeError("GLB header declares a length of " + std::to_string(declared) + " bytes, but the file has " +
                         std::to_string(size) + " (truncated?)");
    size = declared;   // tinygltf ignores bytes past the declared length, as some exporters pad files
    if (size < 20) return makeError("GLB has no JSON chunk: the file ends after its 12-byte header");
    uint32_t jsonLength = word(bytes, 12), jsonType = word(bytes, 16);
    if (jsonType != kJsonChunk)
        return makeError("GLB's first chunk has type " + hex(jsonType) + "; glTF 2.0 requires the JSON chunk (" +
                         hex(kJsonChunk) + ") first");
    if (jsonLength == 0) return makeError("GLB JSON chunk is empty (chunkLength 0)");
    if (jsonLength > size - 20)
        return makeError("GLB JSON chunk declares " + std::to_string(jsonLength) + " bytes, but only " +
                         std::to_string(size - 20) + " follow its chunk header (truncated, or an oversized chunkLength)");
    size_t next = 20 + size_t(jsonLength);
    if (next == size) return okStatus();   // no BIN chunk
    if (size - next < 8)
        return makeError("GLB has " + std::to_string(size - next) + " stray bytes after the JSON chunk (a chunk header is 8)");
    uint32_t binLength = word(bytes, next), binType = word(bytes, next + 4);
    if (binType == kBinChunk && binLength > size - next - 8)
        return makeError("GLB BIN chunk declares " + std::to_string(binLength) + " bytes, but only " +
                         std::to_string(size - next - 8) + " follow its chunk header (truncated, or an oversized chunkLength)");
    return okStatus();
}

}  // namespace caustics::scene::gltf
