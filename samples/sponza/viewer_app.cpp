#include "viewer_app.h"

#include <chrono>
#include <cstdio>

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl2.h>

#include "frame_budget.h"
#include "finite_output.h"
#include "image_file.h"
#include "viewer_context.h"
#include "viewer_ui.h"

namespace caustics::sample {
namespace {

void report(ViewerContext& v, const std::string& message, bool isError) {
    std::fprintf(isError ? stderr : stdout, "caustics-sponza: %s\n", message.c_str());
    v.state.lastMessage = message;
}

void processInput(ViewerContext& v, float seconds) {
    ImGuiIO& io = ImGui::GetIO();
    for (const InputEvent& e : v.input.take()) {
        if (e.kind == InputEvent::Kind::KeyPress && (!io.WantCaptureKeyboard || e.key == GLFW_KEY_ESCAPE)) handleKeyPress(v, e.key);
        if (e.kind == InputEvent::Kind::Scroll && !io.WantCaptureMouse) v.camera.scroll(e.amount);
    }
    static double lastX = 0, lastY = 0;
    double x, y;
    glfwGetCursorPos(v.window, &x, &y);
    bool look = !io.WantCaptureMouse && (glfwGetMouseButton(v.window, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS ||
                                         glfwGetMouseButton(v.window, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS);
    if (look) v.camera.drag(float(x - lastX), float(y - lastY));
    lastX = x;
    lastY = y;
    if (io.WantCaptureKeyboard) return;
    auto axis = [&](int plus, int minus) { return float(v.input.isDown(plus)) - float(v.input.isDown(minus)); };
    glm::vec3 axes{axis(GLFW_KEY_D, GLFW_KEY_A), axis(GLFW_KEY_E, GLFW_KEY_Q), axis(GLFW_KEY_W, GLFW_KEY_S)};
    if (axes != glm::vec3(0.0f)) v.camera.move(axes, seconds);
}

// framesInFlight is fixed at CausticsModule::create (it sizes the per-frame scene tables): the only
// edit that builds a new module. Every other setting is per frame (setSettings).
Status rebuildModule(ViewerContext& v) {
    uint32_t before = (*v.module)->settings().framesInFlight;
    v.renderer.reset();
    v.module->reset();
    CAUSTICS_TRY(*v.module, CausticsModule::create(v.device, *v.scene, *v.gpuScene, v.state.settings));
    CAUSTICS_TRY(v.renderer, FrameRenderer::create(v.device, **v.module, v.state.width, v.state.height));
    ++v.moduleBuilds;
    report(v, "rebuilt the caustics module: framesInFlight " + std::to_string(before) + " -> " +
                  std::to_string(v.state.settings.framesInFlight) + " is fixed at creation", false);
    return okStatus();
}

// Settings go to the module at once through setSettings; lights go through the live scene (the
// animation writes them into the scene every frame), so neither waits for anything.
Status applyEdits(ViewerContext& v) {
    if (v.state.settingsChanged) {
        v.state.settingsChanged = false;
        if (v.state.settings.framesInFlight != (*v.module)->settings().framesInFlight) {
            if (Status st = v.state.settings.validate(); !st) {
                v.state.settings = (*v.module)->settings();
                report(v, st.message(), true);
            } else {
                CAUSTICS_CHECK(rebuildModule(v));
            }
        } else if (Status st = (*v.module)->setSettings(v.state.settings); !st) {
            v.state.settings = (*v.module)->settings();
            report(v, st.message(), true);
        } else {
            ++v.liveSettingsChanges;
        }
    }
    if (v.state.lightsChanged) {
        v.state.lightsChanged = false;
        ++v.liveLightEdits;
    }
    int width = 0, height = 0;
    glfwGetFramebufferSize(v.window, &width, &height);
    if (width > 0 && height > 0 && (uint32_t(width) != v.state.width || uint32_t(height) != v.state.height)) {
        CAUSTICS_CHECK(checkFrameFitsDevice(*v.device, **v.module, uint32_t(width), uint32_t(height), v.state.frame));
        v.state.width = uint32_t(width);
        v.state.height = uint32_t(height);
        v.renderer.reset();
        CAUSTICS_TRY(v.renderer, FrameRenderer::create(v.device, **v.module, v.state.width, v.state.height));
    }
    return okStatus();
}

// Advances the clocks by the last frame's time (fixed under --script) and writes this frame's poses
// and lights into the scene the module reads.
void animateScene(ViewerContext& v, float seconds) {
    v.animation.toggles = v.state.animation;
    if (v.state.frame > 0) v.animation.advance(v.fixedClock ? kFixedFrameSeconds : seconds);
    v.animation.apply(*v.scene, v.state.lights);
    v.state.glassCount = v.animation.glassCount();
    v.state.objectSeconds = v.animation.objectSeconds();
    v.state.lightSeconds = v.animation.lightSeconds();
}

void recordMeasurements(ViewerContext& v, double frameMs) {
    const rg::RenderGraph& graph = v.renderer->graph();
    v.state.frameMs.add(float(frameMs));
    v.state.passOrder.clear();
    for (const auto& pass : graph.desc().passes) {
        if (auto ms = graph.timings().latestMs(pass.name)) {
            v.state.passMs[pass.name].add(float(*ms));
            v.state.passOrder.push_back(pass.name);
        }
    }
    v.state.stats = v.renderer->stats();
}

void drawFrame(ViewerContext& v) {
    const FrameImages& img = v.renderer->images();
    int fbw, fbh;
    glfwGetFramebufferSize(v.window, &fbw, &fbh);
    glViewport(0, 0, fbw, fbh);
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    // Our rows are top-first; OpenGL's raster origin is the bottom-left: draw flipped.
    glRasterPos2f(-1.0f, 1.0f);
    glPixelZoom(float(fbw) / float(img.width), -float(fbh) / float(img.height));
    glDrawPixels(int(img.width), int(img.height), GL_RGBA, GL_UNSIGNED_BYTE, img.display.data());
    ImGui_ImplOpenGL2_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    if (v.state.showUi) drawViewerPanel(v.state, v.camera);
    ImGui::Render();
    ImGui_ImplOpenGL2_RenderDrawData(ImGui::GetDrawData());
}

void takeScreenshots(ViewerContext& v) {
    if (v.state.screenshotRequested) {
        v.state.screenshotRequested = false;
        std::string stem = "caustics-screenshot-" + std::to_string(v.state.frame);
        v.pendingScreenshots.push_back(stem + ".png");
        v.pendingScreenshots.push_back(stem + ".exr");
    }
    for (const std::string& path : v.pendingScreenshots) {
        Status st = writeScreenshot(v, path);
        report(v, st ? "wrote " + path : st.message(), !st);
    }
    v.pendingScreenshots.clear();
}

int loop(ViewerContext& v, const Script& script) {
    const CliOptions& o = *v.options;
    size_t nextCommand = 0;
    auto last = std::chrono::steady_clock::now();
    float seconds = 0.0f;
    while (!glfwWindowShouldClose(v.window) && !v.state.quit && !(o.framesGiven && v.state.frame >= o.frames)) {
        glfwPollEvents();
        for (; nextCommand < script.commands.size() && script.commands[nextCommand].frame <= v.state.frame; ++nextCommand) {
            const ScriptCommand& c = script.commands[nextCommand];
            if (Status st = runScriptCommand(v, c.words, c.where); !st) {
                std::fprintf(stderr, "caustics-sponza: %s\n", st.message().c_str());
                return 1;
            }
        }
        processInput(v, seconds);
        if (v.state.quit) {
            std::printf("caustics-sponza: quit (Escape or script) at frame %u\n", v.state.frame);
            break;
        }
        if (Status st = applyEdits(v); !st) {
            std::fprintf(stderr, "caustics-sponza: %s\n", st.message().c_str());
            return 1;
        }
        animateScene(v, seconds);
        scene::Camera camera = v.camera.camera();
        fitClipPlanes(camera, v.bounds);
        if (Status st = v.renderer->render(camera, v.state.frame, true); !st) {
            std::fprintf(stderr, "caustics-sponza: frame %u: %s\n", v.state.frame, st.message().c_str());
            return 1;
        }
        auto now = std::chrono::steady_clock::now();
        seconds = std::chrono::duration<float>(now - last).count();
        last = now;
        recordMeasurements(v, 1000.0 * seconds);
        drawFrame(v);
        takeScreenshots(v);
        glfwSwapBuffers(v.window);
        ++v.state.frame;
    }
    std::printf("caustics-sponza: the caustics module was built %u time(s); %u light edits and %u settings changes "
                "went to it live\n", v.moduleBuilds, v.liveLightEdits, v.liveSettingsChanges);
    if (!o.outPath.empty()) {
        const FrameImages& img = v.renderer->images();
        if (Status st = writeFiniteRenderedImage(o.outPath, img.width, img.height, img.display, img.hdr); !st) {
            std::fprintf(stderr, "caustics-sponza: %s\n", st.message().c_str());
            return 1;
        }
        std::printf("wrote %s (%ux%u, the last frame shown)\n", o.outPath.c_str(), img.width, img.height);
    }
    return 0;
}

}  // namespace

int runViewer(rhi::DeviceHandle device, scene::Scene& scene, const scene::GpuScene& gpuScene,
              std::unique_ptr<CausticsModule>& module, const CliOptions& o, const Script& script) {
    if (!glfwInit()) {
        std::fprintf(stderr, "caustics-sponza: glfwInit failed (no display? under CI use xvfb-run)\n");
        return 1;
    }
    ViewerContext v;
    v.window = glfwCreateWindow(int(o.width), int(o.height), "caustics-sponza", nullptr, nullptr);
    if (!v.window) {
        std::fprintf(stderr, "caustics-sponza: cannot open a %ux%u window\n", o.width, o.height);
        glfwTerminate();
        return 1;
    }
    glfwMakeContextCurrent(v.window);
    glfwSwapInterval(0);
    v.input.attach(v.window);   // before ImGui's callbacks, which chain to these
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;   // no imgui.ini left in the working folder
    ImGui::StyleColorsDark();
    ImGui_ImplGlfw_InitForOpenGL(v.window, true);
    ImGui_ImplOpenGL2_Init();

    v.device = device;
    v.scene = &scene;
    v.gpuScene = &gpuScene;
    v.module = &module;
    v.options = &o;
    v.bounds = computeSceneBounds(scene);
    v.camera = ViewerCamera(cameraFromOptions(scene, o), v.bounds.radius());
    v.state.settings = module->settings();
    v.state.lights = scene.lights;
    v.animation = SceneAnimation::capture(scene);
    v.state.animation = o.animation.toggles;
    v.fixedClock = !o.scriptPath.empty();
    v.state.sceneCameras = scene.cameras;
    v.state.sceneName = scene.name + (scene.isStandIn ? " [stand-in]" : "");
    v.state.deviceName = device->capabilities().adapterName;
    int code = 0;
    if (Status st = applyEdits(v); !st) {   // creates the renderer at the framebuffer's size
        std::fprintf(stderr, "caustics-sponza: %s\n", st.message().c_str());
        code = 1;
    } else {
        code = loop(v, script);
    }
    v.renderer.reset();
    ImGui_ImplOpenGL2_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    glfwDestroyWindow(v.window);
    glfwTerminate();
    return code;
}

}  // namespace caustics::sample
