#pragma once
// The caustic passes of the paper (Komarov et al. 2021, sections 3.2-3.4) as render-graph passes:
//   caustics.maps      raster light-space G-buffers (one texture-array layer per light and cluster of
//                      specular objects whose caustic the camera can see; caustic_map_plan.h)
//   caustics.emitters  the specular texels of every layer, listed per layer
//   caustics.photonPlan  each layer's photons per texel (its share of CausticsSettings::photonsPerFrame)
//   caustics.forward   forward trace from every specular map texel; first-type splat + hit store (3.2)
//   caustics.specularPixels  the specular camera pixels compacted into a list (the backward grid)
//   caustics.backward  camera rays through specular pixels to the first diffuse hit -> spheres (3.3)
//   caustics.spheres   TLAS over the compacted spheres (GPU-written instances, capacity from an earlier
//                      frame's sphere count: caustics.sphereCount reads it back)
//   caustics.gather    stored forward hits x spheres (any-hit density estimate), second type (3.3)
//   caustics.resolve   radiance buffers -> textures
//   caustics.filterTiles / caustics.temporal / caustics.atrous   the filter (3.4), when settings.filter
// docs/caustics.md explains every choice the paper leaves open.
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "caustics/camera_constants.h"
#include "caustics/caustic_layer_plan.h"
#include "caustics/caustic_map_plan.h"
#include "caustics/caustics_settings.h"
#include "caustics/gbuffer.h"
#include "caustics/memory_report.h"
#include "caustics/scene_bindings.h"
#include "caustics/render_graph/render_graph.h"
#include "caustics/rhi/device.h"
#include "caustics/scene/gpu_scene.h"
#include "caustics/scene/scene.h"
#include "common/caustic_stats.h"

namespace caustics {

// The slots of the small statistics buffer every frame writes, named once for the shaders and C++
// (shaders/common/caustic_stats.h, where each is explained).
using shader::kStatAccumulationGiveUps;
using shader::kStatBackwardLaunches;
using shader::kStatCount;
using shader::kStatDispatchedTexels;
using shader::kStatEmitterTexels;
using shader::kStatFixedPointScale;
using shader::kStatForwardSegments;
using shader::kStatGatherHits;
using shader::kStatGatherLaunches;
using shader::kStatRaysPerLight;
using shader::kStatSaturatedAdds;
using shader::kStatSpecularPixels;
using shader::kStatSphereCapacity;
using shader::kStatSpheres;
using shader::kStatSpheresDropped;
using shader::kStatSplats;
using shader::kStatStoredHitAttempts;

// One stored forward diffuse hit (std430, 64 bytes; GLSL mirror CausticHitRecord in
// shaders/common/caustic_hit.h). It carries the photon's flux, its incoming direction and the
// receiver's glTF BRDF parameters, so a gather evaluates the same BRDF as the splat and direct
// lighting (shaders/common/bsdf.h). The two directions are octahedral snorm16 x 2 (80 -> 64 bytes,
// docs/caustics.md "Memory"); causticHitNormal / causticHitIncoming decode them.
struct CausticHit {
    glm::vec3 position;
    uint32_t objectId;           // instance index + 1
    glm::vec3 flux;              // photon flux, lm per channel
    uint32_t light;
    glm::vec3 baseColor;         // linear; a specular material's diffuse layer stores dielectricF0 = 0
    float dielectricF0;
    uint32_t normal;             // unit shading normal on the side the photon arrived from (octahedral)
    uint32_t incoming;           // unit, from the hit back along the photon's last segment (wi; octahedral)
    uint32_t metallicRoughness;  // unorm16 x 2: metallic (low half), roughness (high half)
    float transmission;
};
static_assert(sizeof(CausticHit) == 64);
glm::vec3 causticHitNormal(const CausticHit& hit);
glm::vec3 causticHitIncoming(const CausticHit& hit);

// One backward (second-type) integration sphere (std430, 64 bytes), appended by caustics.backward: the
// first min(kStatSpheres, kStatSphereCapacity) entries of CausticOutputs::spheres are valid.
struct CausticSphere {
    glm::vec3 centre;
    float radius;
    glm::vec3 transmittance; // camera-path throughput through the specular chain
    uint32_t objectId;
    glm::vec3 normal;        // unit, on the side the camera path arrived from
    uint32_t pixel;          // the camera pixel it gathers for (y x W + x)
    glm::vec3 outgoing;      // unit, from the receiver back along the camera path (wo of the gather's BRDF)
    uint32_t likelyPath;     // 1: every specular event took its most probable lobe (the filter's guides)
};
static_assert(sizeof(CausticSphere) == 64);

// The filter history of one view (paper 3.4, docs/caustics.md "Filter", "History", "Memory"): the
// temporal accumulation (before the spatial passes), its luminance deviation, history length and the
// G-buffer guides it was made with, kept per listed 8x8 tile in a pool of `poolTiles` tiles (not per
// screen pixel: the memory follows the caustics' coverage), and per screen tile its state and pool tile.
// Ping-ponged: [parity] is last frame's, which caustics.temporal reads while it writes [parity ^ 1]
// (no copy pass). Each view (camera, split-screen half, reflection probe) owns one; sized on first use,
// the pool grown from the tile counts the view's frames read back.
struct CausticViewHistory {
    rhi::TextureHandle color[2];    // pool RGBA16F: rgb mean x preExposure, a per-frame luminance deviation
    rhi::TextureHandle guides[2];   // pool RG32UI: half depth and n, normal, object id (caustic_filter/shaders/temporal_thread.h)
    // R32UI per 8x8 pixel tile (docs/caustics.md "Filter", "Tiles"): how many more frames the tile's
    // history is kept, and the tile's pool tile (~0u: none, its history is gone).
    rhi::TextureHandle tiles[2];
    rhi::TextureHandle slots[2];
    uint32_t poolTiles = 0;         // the pool's capacity in tiles
    // A grown pool (docs/caustics.md "Memory"): the smaller pool's textures, whose copy the next graph
    // built reads it copies into the new ones first (caustics.filterHistoryGrow), so that growing keeps
    // the history; `rows` of 8x8 tiles. While it is set, color and guides were just created, so the
    // next graph built imports them with undefined contents.
    struct PoolGrowth {
        rhi::TextureHandle color[2], guides[2];
        uint32_t rows = 0;
    };
    std::optional<PoolGrowth> growth;
    float preExposure[2] = {1.0f, 1.0f};   // the pre-exposure each copy was stored with
    // Per frame slot: the tiles the frame listed (4 bytes, Readback memory) and whether it was recorded.
    std::vector<rhi::BufferHandle> tileCounts;
    std::vector<uint8_t> tileCountRecorded;
    uint32_t parity = 0;
    uint32_t width = 0, height = 0;
    // True once a frame's caustics.temporal pass has been RECORDED (graph execution), so a graph that is
    // built and never executed does not make the history look valid. `parity` is then the copy it wrote.
    bool valid = false;
    // The same two as left by the last BUILT graph. A host may build frame n + 1 before it executes frame
    // n (a render thread ahead of the GPU): frame n + 1 then reads the copy frame n writes, and
    // caustics.temporal checks at execution that the last executed frame did write it (else it ignores
    // the history, as after a cut). docs/embedding.md "Frames and views".
    uint32_t builtParity = 0;
    bool builtValid = false;
    // A build that never executed (a graph built to be compiled only, then dropped) is undone when the
    // next build is for the same or an earlier frame: the frame it built and the state before it, and
    // the frame the last executed caustics.temporal belonged to.
    std::optional<uint32_t> lastBuiltFrame, lastExecutedFrame;
    uint32_t parityBeforeLastBuild = 0;
    bool validBeforeLastBuild = false;
    // The CausticsView this history belongs to (0: CausticResources' own): per-view state of the
    // module (the sphere-count readbacks) is keyed by it, never by an address.
    uint64_t viewId = 0;
    // The second type's own history, filtered on the receiver seen through the glass (docs/caustics.md
    // "Second-type guides"); made when a frame filters with the second type on.
    std::shared_ptr<CausticViewHistory> secondType;
};

// Objects that live across frames: pipelines, the sphere BLAS/TLAS. Create once per device and scene
// (the sphere TLAS grows with the output size). `framesInFlight`: how many frames the host may have
// on the GPU at once (per-frame binding sets are kept that long).
class CausticResources {
public:
    CausticResources();
    ~CausticResources();
    CausticResources(CausticResources&&) noexcept;
    CausticResources& operator=(CausticResources&&) noexcept;

    static Result<CausticResources> create(rhi::IDevice& device, uint32_t framesInFlight = 3);

    struct Impl;
    Impl* impl() { return impl_.get(); }

private:
    std::unique_ptr<Impl> impl_;
};

// Persistent GPU memory (memory_report.h), names prefixed "caustics." / `prefix`: the sphere AABB,
// BLAS and TLAS of the second type and the sphere-count readbacks; and one view's filter history.
void appendCausticMemory(CausticResources& resources, std::vector<MemoryEntry>& out);
void appendHistoryMemory(const CausticViewHistory& history, const std::string& prefix, std::vector<MemoryEntry>& out);
// Makes the ray-tracing pipelines and shader tables for scenes bound with `sceneLayout` (their upload
// submits and waits): CausticsModule::prepare calls it so that addCausticPasses never submits.
Status prepareCausticPipelines(CausticResources& resources, const rhi::BindingLayoutHandle& sceneLayout);
// Releases what `resources` keeps for view `viewId` (its sphere-count readbacks): called for a
// destroyed view, whose frames the host has finished (the RHI defers the buffers' destruction anyway).
void releaseCausticView(CausticResources& resources, uint64_t viewId);

struct CausticFrameInputs {
    rhi::IDevice* device = nullptr;
    const scene::Scene* scene = nullptr;
    const scene::GpuScene* gpuScene = nullptr;
    const SceneBindings* sceneBindings = nullptr;
    GBuffer gbuffer;                   // W x H, this frame's
    CameraConstants camera;            // prevViewProj = last frame's viewProj (filter reprojection)
    CausticsSettings settings;
    uint32_t frameIndex = 0;           // the frame number: seeds the photons (FrameInputs::frameIndex)
    std::optional<uint32_t> frameSlot; // the frame-in-flight slot (< settings.framesInFlight); unset:
                                       // frameIndex % framesInFlight
    // Filled when the graph executes (the module's view.begin, first in the graph): the camera constants
    // with the previous view-projection the view had then; null: `camera` as built.
    std::shared_ptr<const CameraConstants> executedCamera;
    bool resetHistory = false;         // camera cut: the filter forgets the past
    // The view's filter history; null: one history owned by CausticResources (a single view).
    CausticViewHistory* history = nullptr;
    // The scene TLAS as a graph resource when it is rebuilt this frame (frame_context.h); else invalid.
    rg::RgAccelStruct sceneTlas;
    // This frame's photon budget when the module steers it (CausticsSettings::causticTimeTargetMs);
    // none: settings.photonsPerFrame.
    std::optional<uint32_t> photonsPerFrame;
    // Separate first- and second-type buffers and textures (CausticOutputs::firstType, secondType), for
    // an AOV or a test that shows one type. false: both types accumulate into one buffer and resolve
    // to CausticOutputs::radiance alone (docs/caustics.md, "Memory"; CausticsModule asks for the
    // separate ones only for the FirstType / SecondType AOVs).
    bool separateTypes = true;
};

// The second type's own filter guides (caustics.secondTypeGuides; docs/caustics.md "Second-type guides"):
// at a pixel whose camera path went through glass to a diffuse receiver, that receiver's linear depth
// (clip w) and screen motion (last frame's texel-centre position minus this frame's, pixels) in
// depthMotion (RGBA16F: depth, motion x, motion y, last frame's depth), its normal facing the arriving path
// (RGBA16F xyz, w the photon weight) and its object id (R32UI, instance + 1); zeros (id 0) at every other
// pixel.
struct SecondTypeGuides {
    rg::RgTexture depthMotion, normal, objectId;
    bool valid() const { return depthMotion.valid() && normal.valid() && objectId.valid(); }
};

struct CausticOutputs {
    rg::RgTexture radiance;     // RGBA32F W x H, first + second type, filtered when settings.filter
    rg::RgTexture firstType;    // RGBA32F, unfiltered (invalid unless separateTypes)
    rg::RgTexture secondType;   // RGBA32F, unfiltered (black when settings.secondType is off; invalid unless separateTypes;
                                // filtered and in list order when filtered apart without separateTypes)
    rg::RgBuffer firstTypeBuffer;   // float or fixed-point RGB per pixel (both types unless separateTypes)
    rg::RgBuffer secondTypeBuffer;  // invalid unless separateTypes
    rg::RgBuffer hits;          // CausticHit[maxStoredHits]; invalid when settings.secondType is off (none stored)
    rg::RgBuffer stats;         // uint32[kStatCount]
    rg::RgBuffer layerPlans;    // CausticLayerPlanGpu per plan.maps entry (invalid without maps)
    rg::RgBuffer spheres;       // CausticSphere[W x H], the first min(kStatSpheres, kStatSphereCapacity)
                                // valid (invalid when the second type did not run)
    SecondTypeGuides secondTypeGuides;   // invalid unless the second type ran (maps planned, settings.secondType)
    // The second type in list order (common/specular_list.h; filtered apart without separateTypes):
    // secondType and secondTypeGuides hold one texel per entry of specularPixels (each entry's pixel
    // index; the first min(kStatSpecularPixels, kStatSphereCapacity) are this frame's), kSpecularListRow
    // texels to a row, instead of one per pixel (docs/caustics.md "Second-type memory").
    bool secondTypeListOrder = false;
    rg::RgBuffer specularPixels;
    rg::RgBuffer filterTiles;   // uint32 (tiles the filter ran on, 1, 1) when settings.filter (docs/caustics.md "Tiles")
    rg::RgTexture mapObjectIds; // R32_UINT array, one layer per planned map (instance + 1; invalid if none)
    CausticMapPlan plan;        // which lights got maps, their frusta, which were skipped
    bool floatAtomics = true;   // false: the buffers hold fixed point, value x fixedPointScale
    bool wideFixedPoint = false;   // fixed point in one uint64 per channel (else one uint32)
    float fixedPointScale = 0.0f;  // fixed point only: kFixedPointScale(64) x the frame's pre-exposure
};

// Fixed-point radiance words (devices without float atomics; docs/caustics.md "Fixed point") hold
// value x scale, stochastically rounded, with scale = kFixedPointScale (uint32 words) or
// kFixedPointScale64 (uint64 words, shaderBufferInt64Atomics) times the frame's pre-exposure
// (settings.exposure x scene.exposure, what the composite multiplies by): with pre-exposed values near
// 1 for white, uint32 words resolve 1.5e-5 of white and saturate at 65535 x white per pixel and frame,
// uint64 words resolve 2.3e-10 and saturate at 4.3e9 x white.
inline constexpr float kFixedPointScale = 65536.0f;
inline constexpr float kFixedPointScale64 = 4294967296.0f;
// The scale of one frame; a non-finite or non-positive pre-exposure counts as 1.
float fixedPointScale(bool wideWords, float preExposure);

// Upper bound of the forward pass's ray launches for the plan (the device-limit check and the grid of a
// device without indirect ray dispatch).
uint64_t forwardLaunchBound(const CausticsSettings& settings, const CausticMapPlan& plan);

Result<CausticOutputs> addCausticPasses(rg::RenderGraph& graph, CausticResources& persistent,
                                        const CausticFrameInputs& inputs);

// What a host should hear about a finished frame, from its read-back stats buffer (uint32[kStatCount]):
// hit-buffer overflow (the second type then misses the dropped hits), naming the setting, float
// accumulation give-ups, and second-type spheres dropped because the sphere TLAS was too small.
std::vector<std::string> causticStatsWarnings(std::span<const uint32_t> stats, const CausticsSettings& settings);

}  // namespace caustics
