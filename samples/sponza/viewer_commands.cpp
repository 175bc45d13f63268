#include <cmath>

#include <GLFW/glfw3.h>

#include "animation_options.h"
#include "image_file.h"
#include "settings_fields.h"
#include "viewer_context.h"

namespace caustics::sample {
namespace {

Result<float> number(const std::string& text, const std::string& where) {
    CAUSTICS_TRY(double v, parseFiniteNumber(where, text));
    return float(v);
}

Result<glm::vec3> vec3At(const std::vector<std::string>& w, size_t first, const std::string& where) {
    if (w.size() < first + 3) return makeError(where + ": expected three numbers after '" + w[first - 1] + "'");
    glm::vec3 v(0.0f);
    for (int i = 0; i < 3; ++i) {
        CAUSTICS_TRY(v[i], number(w[first + size_t(i)], where));
    }
    return v;
}

Status cameraCommand(ViewerContext& v, const std::vector<std::string>& w, const std::string& where) {
    const std::string& what = w[1];
    if (what == "reset" && w.size() == 2) v.camera.reset();
    else if (what == "mode" && w.size() == 3 && (w[2] == "orbit" || w[2] == "fly"))
        v.camera.setMode(w[2] == "orbit" ? CameraMode::Orbit : CameraMode::Fly);
    else if (what == "drag" && w.size() == 4) {
        CAUSTICS_TRY(float dx, number(w[2], where));
        CAUSTICS_TRY(float dy, number(w[3], where));
        v.camera.drag(dx, dy);
    } else if (what == "move" && w.size() == 6) {
        CAUSTICS_TRY(glm::vec3 axes, vec3At(w, 2, where));
        CAUSTICS_TRY(float seconds, number(w[5], where));
        v.camera.move(axes, seconds);
    } else if (what == "gltf" && w.size() == 3) {
        CAUSTICS_TRY(float index, number(w[2], where));
        if (index < 0 || size_t(index) >= v.state.sceneCameras.size())
            return makeError(where + ": the scene has " + std::to_string(v.state.sceneCameras.size()) + " cameras");
        v.state.sceneCameraIndex = int(index);
        v.camera.setView(v.state.sceneCameras[size_t(index)]);
    } else if (what == "look" && w.size() == 8) {
        scene::Camera c = v.camera.camera();
        CAUSTICS_TRY(c.eye, vec3At(w, 2, where));
        CAUSTICS_TRY(c.target, vec3At(w, 5, where));
        if (glm::length(c.target - c.eye) <= 0.0f) return makeError(where + ": eye and target coincide");
        v.camera.setView(c);
    } else {
        return makeError(where + ": camera takes reset | mode orbit|fly | drag DX DY | move RIGHT UP FORWARD SECONDS | "
                                 "gltf N | look EX EY EZ TX TY TZ");
    }
    return okStatus();
}

Status lightCommand(ViewerContext& v, const std::vector<std::string>& w, const std::string& where) {
    CAUSTICS_TRY(float index, number(w[1], where));
    if (index < 0 || size_t(index) >= v.state.lights.size())
        return makeError(where + ": light " + w[1] + " does not exist (the scene has " + std::to_string(v.state.lights.size()) + ")");
    scene::Light& l = v.state.lights[size_t(index)];
    const std::string& what = w[2];
    if (what == "intensity" && w.size() == 4) {
        CAUSTICS_TRY(l.intensity, number(w[3], where));
    } else if (what == "position" && w.size() == 6) {
        CAUSTICS_TRY(l.position, vec3At(w, 3, where));
    } else if (what == "direction" && w.size() == 6) {
        CAUSTICS_TRY(glm::vec3 d, vec3At(w, 3, where));
        if (!(glm::length(d) > 0.0f)) return makeError(where + ": the direction is zero");
        l.direction = glm::normalize(d);
    } else if (what == "cone" && w.size() == 5) {
        CAUSTICS_TRY(float inner, number(w[3], where));
        CAUSTICS_TRY(float outer, number(w[4], where));
        if (!(inner >= 0.0f && inner <= outer && outer <= 90.0f))
            return makeError(where + ": cone angles must satisfy 0 <= inner <= outer <= 90 degrees");
        l.innerConeAngle = glm::radians(inner);
        l.outerConeAngle = glm::radians(outer);
    } else {
        return makeError(where + ": light N takes intensity X | position X Y Z | direction X Y Z | cone INNER OUTER (degrees)");
    }
    v.state.lightsChanged = true;
    return okStatus();
}

Result<bool> onOff(const std::string& word, const std::string& where, const char* what) {
    if (word == "on") return true;
    if (word == "off") return false;
    return makeError(where + ": " + what + " takes on or off, not '" + word + "'");
}

// animate objects on|off | light N orbit|still | speed X | pause on|off
Status animateCommand(ViewerContext& v, const std::vector<std::string>& w, const std::string& where) {
    AnimationToggles& a = v.state.animation;
    const std::string& what = w[1];
    if (what == "objects" && w.size() == 3) {
        CAUSTICS_TRY(a.objects, onOff(w[2], where, "animate objects"));
    } else if (what == "pause" && w.size() == 3) {
        CAUSTICS_TRY(a.paused, onOff(w[2], where, "animate pause"));
    } else if (what == "speed" && w.size() == 3) {
        CAUSTICS_TRY(float speed, number(w[2], where));
        if (!(speed > 0.0f && speed <= kMaxAnimationSpeed))
            return makeError(where + ": animate speed must be within (0, " + std::to_string(int(kMaxAnimationSpeed)) + "]");
        a.speed = speed;
    } else if (what == "light" && w.size() == 4 && (w[3] == "orbit" || w[3] == "still")) {
        CAUSTICS_TRY(float index, number(w[2], where));
        if (index < 0 || index != std::floor(index)) return makeError(where + ": '" + w[2] + "' is not a light index");
        CAUSTICS_CHECK(checkAnimatedLights({.orbitingLights = {uint32_t(index)}}, v.state.lights.size(), where));
        if (w[3] == "orbit") a.orbitingLights.insert(uint32_t(index));
        else a.orbitingLights.erase(uint32_t(index));
    } else {
        return makeError(where + ": animate takes objects on|off | light N orbit|still | speed X | pause on|off");
    }
    return okStatus();
}

}  // namespace

void handleKeyPress(ViewerContext& v, int key) {
    switch (key) {
        case GLFW_KEY_ESCAPE: v.state.quit = true; break;
        case GLFW_KEY_F12: v.state.screenshotRequested = true; break;
        case GLFW_KEY_TAB: v.state.showUi = !v.state.showUi; break;
        case GLFW_KEY_R: v.camera.reset(); break;
        case GLFW_KEY_C:
            v.camera.setMode(v.camera.mode() == CameraMode::Orbit ? CameraMode::Fly : CameraMode::Orbit);
            break;
        case GLFW_KEY_G:
            if (!v.state.sceneCameras.empty()) {
                v.state.sceneCameraIndex = (v.state.sceneCameraIndex + 1) % int(v.state.sceneCameras.size());
                v.camera.setView(v.state.sceneCameras[size_t(v.state.sceneCameraIndex)]);
            }
            break;
        case GLFW_KEY_M: v.state.animation.objects = !v.state.animation.objects; break;
        case GLFW_KEY_O: {   // light 0's orbit on/off
            std::set<uint32_t>& orbiting = v.state.animation.orbitingLights;
            if (orbiting.count(0)) orbiting.erase(0);
            else if (!v.state.lights.empty()) orbiting.insert(0);
            break;
        }
        case GLFW_KEY_P: v.state.animation.paused = !v.state.animation.paused; break;
        default: break;
    }
}

Status runScriptCommand(ViewerContext& v, const std::vector<std::string>& w, const std::string& where) {
    const std::string& command = w[0];
    if (command == "set") {
        if (Status st = setSettingsField(v.state.settings, w[1], w[2]); !st) return makeError(where + ": " + st.message());
        v.state.settingsChanged = true;
    } else if (command == "key") {
        int key = keyFromName(w[1]);
        if (key < 0) return makeError(where + ": unknown key '" + w[1] + "' (escape, tab, f12, a-z, 0-9, ...)");
        // A tap: press and release before the frame looks at its events, as a quick user would.
        v.input.onKey(key, GLFW_PRESS);
        v.input.onKey(key, GLFW_RELEASE);
    } else if (command == "screenshot") {
        const std::string& path = w[1];
        if (path.size() < 5 || (path.substr(path.size() - 4) != ".png" && path.substr(path.size() - 4) != ".exr"))
            return makeError(where + ": screenshot '" + path + "' must end in .png or .exr");
        v.pendingScreenshots.push_back(path);
    } else if (command == "camera") {
        return cameraCommand(v, w, where);
    } else if (command == "light") {
        return lightCommand(v, w, where);
    } else if (command == "ui") {
        if (w[1] != "on" && w[1] != "off") return makeError(where + ": ui takes on or off");
        v.state.showUi = w[1] == "on";
    } else if (command == "resize") {
        CAUSTICS_TRY(float width, number(w[1], where));
        CAUSTICS_TRY(float height, number(w[2], where));
        if (!(width >= 16 && height >= 16 && width <= 8192 && height <= 8192))
            return makeError(where + ": resize takes a size within [16, 8192]");
        glfwSetWindowSize(v.window, int(width), int(height));
    } else if (command == "animate") {
        return animateCommand(v, w, where);
    } else if (command == "quit") {
        v.state.quit = true;
    }
    return okStatus();
}

Status writeScreenshot(ViewerContext& v, const std::string& path) {
    if (path.size() > 4 && path.substr(path.size() - 4) == ".exr") {
        const FrameImages& img = v.renderer->images();
        return writeImage(path, FloatImage{img.width, img.height, 4, img.hdr});
    }
    int width = 0, height = 0;
    glfwGetFramebufferSize(v.window, &width, &height);
    std::vector<uint8_t> bottomUp(size_t(width) * size_t(height) * 4), topDown(bottomUp.size());
    glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, bottomUp.data());
    size_t row = size_t(width) * 4;
    for (int y = 0; y < height; ++y)   // OpenGL's origin is the bottom-left; files start at the top
        std::copy_n(bottomUp.data() + size_t(height - 1 - y) * row, row, topDown.data() + size_t(y) * row);
    return writeImage8(path, uint32_t(width), uint32_t(height), topDown);
}

}  // namespace caustics::sample
