#pragma once
// Private to the viewer: everything one frame of the loop touches (viewer_app.cpp runs the loop,
// viewer_commands.cpp executes the --script commands and the keys on it).
#include <memory>
#include <string>
#include <vector>

#include "camera_setup.h"
#include "caustics/caustics_module.h"
#include "cli_options.h"
#include "frame_renderer.h"
#include "scene_animation.h"
#include "viewer_input.h"
#include "viewer_state.h"

struct GLFWwindow;

namespace caustics::sample {

struct ViewerContext {
    rhi::DeviceHandle device;
    scene::Scene* scene = nullptr;
    const scene::GpuScene* gpuScene = nullptr;
    std::unique_ptr<CausticsModule>* module = nullptr;
    std::unique_ptr<FrameRenderer> renderer;
    const CliOptions* options = nullptr;
    GLFWwindow* window = nullptr;
    InputQueue input;
    ViewerState state;
    ViewerCamera camera{scene::Camera{}, 1.0f};
    SceneBounds bounds;
    SceneAnimation animation;
    bool fixedClock = false;                       // --script: kFixedFrameSeconds per frame, not wall time
    uint32_t moduleBuilds = 1;                     // main built the first; only framesInFlight rebuilds
    uint32_t liveLightEdits = 0, liveSettingsChanges = 0;   // frames whose edits went to the module live
    std::vector<std::string> pendingScreenshots;   // written after this frame is drawn
};

// Executes one script command; errors name the script line.
Status runScriptCommand(ViewerContext& v, const std::vector<std::string>& words, const std::string& where);

// A key press (from GLFW or a script tap): Escape quits, F12 screenshots, Tab toggles the panel,
// C switches orbit/fly, R resets the camera, G steps through the glTF cameras, M moves the glass,
// O orbits light 0, P pauses the animation.
void handleKeyPress(ViewerContext& v, int key);

// Writes `path`: .png = the window as shown (panel included, read from the back buffer), .exr = the
// last render's linear HDR image.
Status writeScreenshot(ViewerContext& v, const std::string& path);

}  // namespace caustics::sample
