#pragma once
// The G-buffer contract (pass 1). Every pass after the G-buffer reads these W x H textures
// and nothing else about the camera view; a host engine may supply its own (imported into the graph)
// as long as it follows the formats and encodings below. Background pixels: depth 1, linearDepth 0,
// objectId 0 (the other targets are cleared to 0). Which channels a host must supply, and why, is in
// hostGBufferRequirements() and docs/embedding.md; `depth` is never read by the module.
//
//   depth            D32_FLOAT     hardware depth, 0 near .. 1 far (CameraConstants::proj, Vulkan Z 0..1)
//   normalRoughness  RGBA16_FLOAT  xyz world-space unit shading normal, flipped to face the viewer;
//                                  w glTF perceptual roughness
//   albedoMetallic   RGBA8_UNORM   rgb LINEAR base colour (factor x texture), a metallic
//   optics           RGBA16_FLOAT  x reflectance weight, y transmittance weight, z IOR,
//                                  w 1 if Material::isSpecular() else 0 (see below)
//   linearDepth      R32_FLOAT     view-space distance along the camera axis (metres); 0 = background
//   objectId         R32_UINT      instance index + 1; 0 = background. "Instance index" is the
//                                  instance's position in scene::Scene::instances, which is also its
//                                  TLAS instance id and its row in the instance table (live_scene.h).
//                                  A host G-buffer may hold its own ids instead, with HostGBuffer::objectIdMap
//
// optics.x = metallic + (1 - metallic) * specular * F0(ior)   (normal-incidence reflectance; glTF
//            metallic-roughness + KHR_materials_specular; F0 = ((ior-1)/(ior+1))^2)
// optics.y = (1 - metallic) * transmission                    (KHR_materials_transmission)
#include <cstdint>

#include "caustics/render_graph/resource_handle.h"
#include "caustics/rhi/format.h"
#include "caustics/rhi/resources.h"

namespace caustics {

struct GBufferFormats {
    static constexpr rhi::Format kDepth = rhi::Format::D32_FLOAT;
    static constexpr rhi::Format kNormalRoughness = rhi::Format::RGBA16_FLOAT;
    static constexpr rhi::Format kAlbedoMetallic = rhi::Format::RGBA8_UNORM;
    static constexpr rhi::Format kOptics = rhi::Format::RGBA16_FLOAT;
    static constexpr rhi::Format kLinearDepth = rhi::Format::R32_FLOAT;
    static constexpr rhi::Format kObjectId = rhi::Format::R32_UINT;
};

// Graph handles of one frame's G-buffer (the latest versions: the G-buffer pass's outputs, or the
// host's imported textures).
struct GBuffer {
    rg::RgTexture depth;
    rg::RgTexture normalRoughness;
    rg::RgTexture albedoMetallic;
    rg::RgTexture optics;
    rg::RgTexture linearDepth;
    rg::RgTexture objectId;
    uint32_t width = 0;
    uint32_t height = 0;

    bool valid() const {
        return depth.valid() && normalRoughness.valid() && albedoMetallic.valid() && optics.valid() &&
               linearDepth.valid() && objectId.valid() && width > 0 && height > 0;
    }
};

// Physical textures of a host G-buffer (imported by CausticsModule::addPasses when given). Every
// texture the module reads needs Sampled usage. `depth` is optional (the module never reads it).
struct HostGBuffer {
    rhi::TextureHandle depth, normalRoughness, albedoMetallic, optics, linearDepth, objectId;
    // The state the host leaves them in before the graph runs and wants them in afterwards.
    rhi::ResourceState state = rhi::ResourceState::ShaderResource;
    // Optional: objectId holds the host's own ids. objectIdMapCount (hostId, moduleId) pairs of uint32,
    // sorted by hostId (ascending, unique), moduleId = instance index + 1; a host id the map does not
    // list reads as 0 (background). Storage usage, shader-readable when the graph runs. The module maps
    // every pixel on the GPU (pass gbuffer.object_ids) into its own texture; the host's is only read.
    rhi::BufferHandle objectIdMap;
    uint32_t objectIdMapCount = 0;
};

// Which channels the passes of a configuration read (true = the host must supply it):
//   linearDepth, objectId  always: the first-type splat's visibility test (paper Fig. 4b: same object,
//                          same depth), the filter's reprojection and edge stops;
//   optics                 settings.secondType: the backward pass starts at pixels with optics.w = 1;
//   normalRoughness        settings.filter (edge stops) or our direct lighting/composite;
//   albedoMetallic         our direct lighting/composite (not in causticsOnly mode).
struct HostGBufferRequirements {
    bool normalRoughness = false, albedoMetallic = false, optics = false;
};

struct CausticsSettings;
HostGBufferRequirements hostGBufferRequirements(const CausticsSettings& settings);

// Texture description of each target (usage flags for the accesses are added by the graph).
rhi::TextureDesc gbufferTextureDesc(rhi::Format format, uint32_t width, uint32_t height, const char* name);

}  // namespace caustics
