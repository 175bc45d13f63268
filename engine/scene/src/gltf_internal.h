#pragma once
// Private to the scene library: tinygltf plus the checked accessor reader the importer uses.
#include <cstdint>
#include <filesystem>
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

// Where external URIs may lead (gltf_uris.cpp, docs/viewer.md "Untrusted glTF"): relative URIs resolve
// against modelDir, and the file must be a regular file inside root (both absolute and canonical).
// An empty root (a glTF loaded from memory without LoadOptions::assetRoot) allows no external file.
struct AssetRoot {
    std::filesystem::path modelDir;
    std::filesystem::path root;
};
// `modelDir`: the glTF file's folder ("" when loaded from memory); `assetRoot`: LoadOptions::assetRoot.
Result<AssetRoot> makeAssetRoot(const std::string& modelDir, const std::string& assetRoot);
// The external file `uri` (field "buffers[0].uri") names is a regular file inside the root; else an
// error naming the field, the URI, where it resolves and the root. Opens nothing. `missingOk`: a file
// that does not exist passes (images: tinygltf warns and the texture becomes white).
Status checkUri(const AssetRoot& root, const std::string& field, const std::string& uri, bool missingOk);
// File-system callbacks for tinygltf that apply checkUri's rule to every path tinygltf tries; `root`
// must outlive the loader.
tinygltf::FsCallbacks confinedFileSystem(const AssetRoot& root);

// Checks on the raw file before tinygltf parses it (gltf_preflight.cpp): the GLB header and chunks, and in
// the JSON the asset version, the array fields, extensionsRequired, buffer byteLengths, data URIs,
// byteStrides and external URIs, with errors naming the field, its value and the limit; `warnings` gets
// what is out of spec but usable (camera aspectRatio, zfar <= znear).
Status preflightGlb(const std::vector<unsigned char>& bytes);
Status preflightJson(const unsigned char* json, size_t size, const AssetRoot& root, std::vector<std::string>& warnings);
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
// Out-of-spec factors are clamped with a warning naming the material, the field, its value and the range;
// emission is limited to `maxEmission` cd/m^2.
Material convertMaterial(const tinygltf::Material& material, size_t index, const std::vector<int>& textureToImage,
                         float maxEmission, std::vector<std::string>& warnings);
// KHR_lights_punctual light placed by a node's world transform (it shines along the node's -Z). false +
// `problem`: the light is unusable; `warning` (may be set on success): what was repaired (out-of-spec
// values clamped, the intensity to `maxIntensity`), each with its value and the limit.
bool convertLight(const tinygltf::Light& light, const glm::mat4& world, float maxIntensity, Light& out,
                  std::string& problem, std::string& warning);
// Perspective camera looking down the node's -Z with +Y up.
bool convertCamera(const tinygltf::Camera& camera, const glm::mat4& world, Camera& out, std::string& problem);

}  // namespace caustics::scene::gltf
