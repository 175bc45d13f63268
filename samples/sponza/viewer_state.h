#pragma once
// What the viewer's panel shows and edits, shared by the UI (viewer_ui.cpp), the script
// (viewer_script.h) and the frame loop (viewer_app.cpp).
#include <cstdint>
#include <deque>
#include <map>
#include <string>
#include <vector>

#include "caustics/caustics_settings.h"
#include "caustics/scene/scene.h"
#include "scene_animation.h"
#include "viewer_camera.h"

namespace caustics::sample {

// A fixed-length history of one quantity (ImGui plots it; the panel prints its median).
class History {
public:
    static constexpr size_t kLength = 120;
    void add(float value);
    const std::vector<float>& values() const { return values_; }   // oldest first
    float median() const;

private:
    std::vector<float> values_;
};

struct ViewerState {
    CausticsSettings settings;             // edited; the loop applies it with setSettings
    bool settingsChanged = false;
    std::vector<scene::Light> lights;      // the lights at rest, as edited (the animation turns orbiting ones)
    bool lightsChanged = false;            // an edit this frame: it reaches the module through the live scene
    AnimationToggles animation;            // edited; the loop hands it to SceneAnimation every frame
    std::vector<scene::Camera> sceneCameras;
    int sceneCameraIndex = -1;
    bool showUi = true;
    bool quit = false;
    bool screenshotRequested = false;      // F12: PNG of the window + EXR of the render
    std::string sceneName;
    std::string deviceName;

    // Measured each frame.
    History frameMs;                       // host wall time of a whole frame
    std::map<std::string, History> passMs; // GPU time per render-graph pass
    std::vector<std::string> passOrder;    // as the graph ran them
    std::vector<uint32_t> stats;           // caustic_passes.h kStat* of the last frame
    size_t glassCount = 0;                 // instances the animation moves
    float objectSeconds = 0.0f, lightSeconds = 0.0f;   // the animation clocks
    uint32_t width = 0, height = 0;
    uint32_t frame = 0;
    std::string lastMessage;               // the last screenshot or error, shown in the panel
};

}  // namespace caustics::sample
