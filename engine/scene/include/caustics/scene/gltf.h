#pragma once
// glTF 2.0 import and export (tinygltf). Supported: node hierarchy (matrix or TRS), TRIANGLES
// primitives (indexed or not), PBR metallic-roughness with base-colour textures, KHR_materials_
// transmission / ior / volume / specular / emissive_strength, KHR_lights_punctual and perspective
// cameras. Errors always begin with the file path and name what is wrong; nothing throws.
#include <cstdint>
#include <string>

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

// Writes the scene as glTF 2.0: `.glb` binary or `.gltf` with an embedded (data URI) buffer.
// Textures are embedded as PNG; lights as KHR_lights_punctual; materials with their extensions.
Status writeGltf(const Scene& scene, const std::string& path);

}  // namespace caustics::scene
