#pragma once
// --window: an interactive view. The RHI has no swapchain yet, so each frame's display image is read
// back to the host and drawn with GLFW's OpenGL context (glDrawPixels). Drag with the left mouse button
// to orbit, scroll or W/S to dolly, Esc to quit.
#include "caustics/caustics_module.h"
#include "cli_options.h"
#include "caustics/rhi/device.h"
#include "caustics/scene/scene.h"

namespace caustics::sample {

int runWindow(rhi::DeviceHandle device, CausticsModule& module, const scene::Scene& scene, const CliOptions& options);

}  // namespace caustics::sample
