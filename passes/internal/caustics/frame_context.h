#pragma once
// What every pass of one frame receives from CausticsModule: the scene (CPU + GPU + its binding set,
// set 0 in every pass), the camera constants and their binding set (set 1 in every pass: binding 0 =
// uniform CameraConstants, shaders/common/camera.h), the image size and the settings.
#include <cstdint>

#include "caustics/camera_constants.h"
#include "caustics/caustics_settings.h"
#include "caustics/scene_bindings.h"
#include "caustics/render_graph/resource_handle.h"
#include "caustics/rhi/device.h"
#include "caustics/scene/gpu_scene.h"
#include "caustics/scene/scene.h"

namespace caustics {

inline constexpr uint32_t kSceneSet = 0;    // SceneBindings::set
inline constexpr uint32_t kCameraSet = 1;   // FrameContext::cameraSet
inline constexpr uint32_t kPassSet = 2;     // a pass's own resources

struct FrameContext {
    rhi::IDevice* device = nullptr;
    const scene::Scene* scene = nullptr;
    const scene::GpuScene* gpuScene = nullptr;
    const SceneBindings* sceneBindings = nullptr;
    // The scene TLAS as a graph resource when the module rebuilds it this frame (live scene): passes
    // that trace declare a read so the graph orders them after the build. Invalid for a frozen scene.
    rg::RgAccelStruct sceneTlas;
    const CausticsSettings* settings = nullptr;
    CameraConstants camera;
    rhi::BufferHandle cameraBuffer;           // host-visible uniform buffer holding `camera`
    rhi::BindingLayoutHandle cameraLayout;    // binding 0: ConstantBuffer
    rhi::BindingSetHandle cameraSet;
    uint32_t width = 0, height = 0;
    uint32_t frameIndex = 0;
};

}  // namespace caustics
