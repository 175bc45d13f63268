#include "window_app.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <GLFW/glfw3.h>

#include "frame_renderer.h"
#include "scene_source.h"

namespace caustics::sample {
namespace {

// Orbit camera around the target: yaw/pitch in radians, distance in metres.
struct Orbit {
    glm::vec3 target{0.0f};
    float yaw = 0.0f, pitch = 0.0f, distance = 1.0f;

    static Orbit from(const scene::Camera& c) {
        Orbit o;
        o.target = c.target;
        glm::vec3 d = c.eye - c.target;
        o.distance = std::max(glm::length(d), 1e-3f);
        o.pitch = std::asin(std::clamp(d.y / o.distance, -1.0f, 1.0f));
        o.yaw = std::atan2(d.x, d.z);
        return o;
    }
    void apply(scene::Camera& c) const {
        glm::vec3 d{std::cos(pitch) * std::sin(yaw), std::sin(pitch), std::cos(pitch) * std::cos(yaw)};
        c.eye = target + distance * d;
        c.target = target;
    }
};

struct InputState {
    Orbit orbit;
    bool dragging = false;
    double lastX = 0, lastY = 0;
};

}  // namespace

int runWindow(rhi::DeviceHandle device, CausticsModule& module, const scene::Scene& scene, const CliOptions& o) {
    if (!glfwInit()) {
        std::fprintf(stderr, "caustics-sponza: glfwInit failed (no display?)\n");
        return 1;
    }
    GLFWwindow* window = glfwCreateWindow(int(o.width), int(o.height), "caustics-sponza", nullptr, nullptr);
    if (!window) {
        std::fprintf(stderr, "caustics-sponza: cannot open a window\n");
        glfwTerminate();
        return 1;
    }
    glfwMakeContextCurrent(window);
    glfwSwapInterval(0);
    auto renderer = FrameRenderer::create(device, module, o.width, o.height);
    if (!renderer) {
        std::fprintf(stderr, "caustics-sponza: %s\n", renderer.message().c_str());
        glfwTerminate();
        return 1;
    }
    scene::Camera camera = cameraFromOptions(scene, o);
    InputState input;
    input.orbit = Orbit::from(camera);
    glfwSetWindowUserPointer(window, &input);
    glfwSetScrollCallback(window, [](GLFWwindow* w, double, double dy) {
        auto* s = static_cast<InputState*>(glfwGetWindowUserPointer(w));
        s->orbit.distance *= std::pow(0.9f, float(dy));
    });

    uint32_t frame = 0;
    while (!glfwWindowShouldClose(window) && !(o.framesGiven && frame >= o.frames)) {
        glfwPollEvents();
        if (glfwGetKey(window, GLFW_KEY_ESCAPE) == GLFW_PRESS) break;
        if (glfwGetKey(window, GLFW_KEY_W) == GLFW_PRESS) input.orbit.distance *= 0.97f;
        if (glfwGetKey(window, GLFW_KEY_S) == GLFW_PRESS) input.orbit.distance *= 1.03f;
        double x, y;
        glfwGetCursorPos(window, &x, &y);
        bool down = glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
        if (down && input.dragging) {
            input.orbit.yaw -= float(x - input.lastX) * 0.01f;
            input.orbit.pitch = std::clamp(input.orbit.pitch + float(y - input.lastY) * 0.01f, -1.5f, 1.5f);
        }
        input.dragging = down;
        input.lastX = x;
        input.lastY = y;
        input.orbit.apply(camera);

        Status st = (*renderer)->render(camera, frame++, true);
        if (!st) {
            std::fprintf(stderr, "caustics-sponza: %s\n", st.message().c_str());
            break;
        }
        const FrameImages& img = (*renderer)->images();
        int fbw, fbh;
        glfwGetFramebufferSize(window, &fbw, &fbh);
        glViewport(0, 0, fbw, fbh);
        glClear(GL_COLOR_BUFFER_BIT);
        // Our rows are top-first; OpenGL's raster origin is the bottom-left: draw flipped.
        glRasterPos2f(-1.0f, 1.0f);
        glPixelZoom(float(fbw) / float(img.width), -float(fbh) / float(img.height));
        glDrawPixels(int(img.width), int(img.height), GL_RGBA, GL_UNSIGNED_BYTE, img.display.data());
        glfwSwapBuffers(window);
        if (frame % 30 == 0) {
            auto ms = (*renderer)->graph().passTimeMs("direct_lighting");
            char title[128];
            std::snprintf(title, sizeof(title), "caustics-sponza - %s - direct %.2f ms", scene.name.c_str(), ms ? *ms : 0.0);
            glfwSetWindowTitle(window, title);
        }
    }
    glfwDestroyWindow(window);
    glfwTerminate();
    return 0;
}

}  // namespace caustics::sample
