#pragma once
// glTF 2.0 import and export (tinygltf). Supported: node hierarchy (matrix or TRS), TRIANGLES
// primitives (indexed or not), PBR metallic-roughness with base-colour textures, KHR_materials_
// transmission / ior / volume / specular / emissive_strength, KHR_lights_punctual and perspective
// cameras. Errors always begin with the file path and name what is wrong; nothing throws.
// The file is untrusted input (docs/viewer.md, "Untrusted glTF"): external URIs are confined to the asset
// root, out-of-spec values are refused or clamped with a warning naming the field, its value and the limit.
#include <cstdint>
#include <string>
#include <vector>

#include "caustics/rhi/result.h"
#include "caustics/scene/scene.h"

namespace caustics::scene {

struct LoadOptions {
    // Refuse files beyond these limits (the error names the limit); they guard memory, not features.
    uint64_t maxTriangles = 50'000'000;       // all primitives together
    uint64_t maxVertices = 100'000'000;       // all primitives together
    uint32_t maxTextureDimension = 16384;     // width and height of each image
    uint32_t maxNodes = 1'000'000;
    uint32_t maxInstances = 4'000'000;
    // Brightest light accepted (cd for point and spot lights, lux for directional ones) and brightest
    // emission (cd/m^2); beyond it the value is clamped with a warning. The sun gives ~1.2e5 lux; past
    // ~6.5e4 cd/m^2 the half-float direct-light target overflows (docs/viewer.md, "Untrusted glTF").
    float maxLightIntensity = 1e6f;
    // External buffer and image URIs must name regular files inside this folder (no `..` escape, no
    // absolute path outside it, no device, FIFO or socket; a link counts where it points). Empty: the
    // glTF file's own folder. Widen it for asset packs that keep textures in a sibling folder.
    std::string assetRoot;
    // When a primitive has no normals: true = smooth (area weighted over shared vertices),
    // false = flat, as glTF 2.0 3.7.2.1 asks.
    bool smoothGeneratedNormals = false;
    // Morton-sort each mesh's triangles so BLAS builds trace fast (see mesh_utils.h).
    bool sortTriangles = true;
    // Load images (false: every texture becomes 1x1 white; faster for geometry-only tools).
    bool loadImages = true;
};

// `.gltf` (JSON, external or data-URI buffers) or `.glb` (binary); other extensions are sniffed by
// the "glTF" magic. The scene is named after the file. Instances get objectId = index + 1
// (0 is reserved for "no object").
Result<Scene> loadGltf(const std::string& path, const LoadOptions& options = {});
// The same from bytes in memory (`.glb` or `.gltf` contents, told apart by the "glTF" magic); `name`
// names the scene and starts every error. External URIs resolve in LoadOptions::assetRoot; without one,
// no file is read at all.
Result<Scene> loadGltfFromMemory(const std::vector<unsigned char>& bytes, const std::string& name,
                                 const LoadOptions& options = {});

// Writes the scene as glTF 2.0: `.glb` binary or `.gltf` with an embedded (data URI) buffer.
// Textures are embedded as PNG; lights as KHR_lights_punctual; materials with their extensions.
Status writeGltf(const Scene& scene, const std::string& path);

}  // namespace caustics::scene
