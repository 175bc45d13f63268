#include "gltf_fuzz_target.h"

#include <vector>

#include "caustics/rhi/log.h"
#include "caustics/scene/gltf.h"

namespace caustics::scene::fuzz {

std::string loadOne(const uint8_t* data, size_t size) {
    static const bool quiet = [] {   // the loader's warnings are not under test; printing them is slow
        setLogCallback([](LogLevel, std::string_view) {});
        return true;
    }();
    (void)quiet;
    LoadOptions options;
    options.maxTriangles = 1'000'000;   // declared counts must not make one input slow
    options.maxVertices = 1'000'000;
    options.maxTextureDimension = 1024;
    options.sortTriangles = false;
    const std::string name = "fuzz-input";
    auto result = loadGltfFromMemory(std::vector<unsigned char>(data, data + size), name, options);
    if (result.ok() || result.message().rfind(name + ": ", 0) == 0) return "";
    return "the error does not start with the input's name: " + result.message();
}

}  // namespace caustics::scene::fuzz
