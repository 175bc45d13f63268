#pragma once
// Private to the scene library: tinygltf plus the checked accessor reader the importer uses.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <tiny_gltf.h>
// Declarations only; Debian's libstb provides the definitions.
#include <stb_image.h>
#include <stb_image_write.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

#include "caustics/rhi/result.h"

namespace caustics::scene::gltf {

// A validated view of an accessor's bytes: every element [0, count) lies inside its buffer.
struct AccessorView {
    const uint8_t* data = nullptr;
    size_t stride = 0;
    size_t count = 0;
    int componentType = 0;
    int components = 0;
    bool normalized = false;
};

// Checks that accessor `index` exists, is dense, and fits its buffer view and buffer; `what`
// names the use ("POSITION of mesh 0 primitive 1") in errors. `maxCount` guards memory.
Result<AccessorView> viewAccessor(const tinygltf::Model& model, int index, const std::string& what,
                                  uint64_t maxCount);

// Element i, component c, converted to float (normalized integers per glTF 2.0 3.11).
float readFloat(const AccessorView& view, size_t i, int c);
uint32_t readIndex(const AccessorView& view, size_t i);

const char* typeName(int tinygltfType);
const char* componentTypeName(int componentType);

// Checks on the raw file before tinygltf parses it (gltf_preflight.cpp): the GLB header version, and in
// the JSON the asset version, extensionsRequired and buffer byteLengths, with errors naming the field.
Status preflightGlb(const std::vector<unsigned char>& bytes);
Status preflightJson(const unsigned char* json, size_t size);
bool isSupportedExtension(const std::string& name);
// `text` cut to maxChars with its full length noted: user strings (names, URIs) in messages stay short.
std::string shortened(const std::string& text, size_t maxChars);
// Every run of non-blank characters longer than maxWord shortened (tinygltf's errors quote data URIs).
std::string shortenLongWords(const std::string& text, size_t maxWord = 96);

// Safe JSON-value lookups (tinygltf::Value asserts on a wrong type).
const tinygltf::Value* member(const tinygltf::Value& object, const char* key);
float numberOr(const tinygltf::Value& object, const char* key, float fallback);
glm::vec3 vec3Or(const tinygltf::Value& object, const char* key, const glm::vec3& fallback);
int intOr(const tinygltf::Value& object, const char* key, int fallback);

}  // namespace caustics::scene::gltf

#include "caustics/scene/scene.h"

namespace caustics::scene::gltf {

// glTF material -> optical properties. `textureToImage` maps a glTF texture index to the image
// (== Scene::textures) index, or -1. Warnings go to `warnings`.
Material convertMaterial(const tinygltf::Material& material, const std::vector<int>& textureToImage,
                         std::vector<std::string>& warnings);
// KHR_lights_punctual light placed by a node's world transform (it shines along the node's -Z). false +
// `problem`: the light is unusable; `warning` (may be set on success): what was repaired.
bool convertLight(const tinygltf::Light& light, const glm::mat4& world, Light& out, std::string& problem,
                  std::string& warning);
// Perspective camera looking down the node's -Z with +Y up.
bool convertCamera(const tinygltf::Camera& camera, const glm::mat4& world, Camera& out, std::string& problem);

}  // namespace caustics::scene::gltf
