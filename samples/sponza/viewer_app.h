#pragma once
// --window: the interactive viewer. The RHI has no swapchain, so each frame's display image is read
// back and drawn with GLFW's OpenGL context, and the Dear ImGui panel is drawn over it with ImGui's
// OpenGL2 backend (docs/viewer.md says why, and lists the controls and the --script commands).
#include <memory>

#include "caustics/caustics_module.h"
#include "cli_options.h"
#include "caustics/rhi/device.h"
#include "caustics/scene/gpu_scene.h"
#include "caustics/scene/scene.h"
#include "viewer_script.h"

namespace caustics::sample {

// `scene` must be the one `module` and `gpuScene` were made from: the viewer rewrites its lights and glass
// instances every frame (the module's live scene); only a framesInFlight change rebuilds `module` from it.
// options.animation's lights must exist (main checks them).
// Returns the process exit code.
int runViewer(rhi::DeviceHandle device, scene::Scene& scene, const scene::GpuScene& gpuScene,
              std::unique_ptr<CausticsModule>& module, const CliOptions& options, const Script& script);

}  // namespace caustics::sample
