#include "viewer_ui.h"

#include <algorithm>
#include <cmath>

#include <imgui.h>

#include "caustics/caustic_passes.h"
#include "settings_fields.h"

namespace caustics::sample {
namespace {

constexpr float kDegrees = 57.2957795f;

void plot(const char* label, const History& h, const char* overlay) {
    const std::vector<float>& v = h.values();
    ImGui::PlotLines(label, v.data(), int(v.size()), 0, overlay, 0.0f, FLT_MAX, ImVec2(0, 40));
}

void timingSection(const ViewerState& s) {
    if (!ImGui::CollapsingHeader("Timing (medians)", ImGuiTreeNodeFlags_DefaultOpen)) return;
    char overlay[64];
    std::snprintf(overlay, sizeof(overlay), "frame %.1f ms", double(s.frameMs.median()));
    plot("##frame", s.frameMs, overlay);
    if (ImGui::BeginTable("passes", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchProp)) {
        float total = 0.0f;
        for (const std::string& pass : s.passOrder) {
            auto it = s.passMs.find(pass);
            if (it == s.passMs.end()) continue;
            float ms = it->second.median();
            total += ms;
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(pass.c_str());
            ImGui::TableNextColumn();
            ImGui::Text("%8.3f ms", double(ms));
        }
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted("GPU total");
        ImGui::TableNextColumn();
        ImGui::Text("%8.3f ms", double(total));
        ImGui::EndTable();
    }
    if (auto it = s.passMs.find("caustics.forward"); it != s.passMs.end()) plot("##forward", it->second, "caustics.forward");
}

void countersSection(const ViewerState& s) {
    if (!ImGui::CollapsingHeader("Counters", ImGuiTreeNodeFlags_DefaultOpen) || s.stats.size() < kStatCount) return;
    uint64_t photons = 0;
    for (uint32_t l = 0; l < kMaxCausticLights; ++l) photons += s.stats[kStatRaysPerLight + l];
    uint32_t offered = s.stats[kStatStoredHitAttempts];
    uint32_t kept = std::min(offered, s.settings.maxStoredHits);
    ImGui::Text("photon paths (forward rays) %llu", static_cast<unsigned long long>(photons));
    ImGui::Text("first-type splats           %u", s.stats[kStatSplats]);
    ImGui::Text("stored hits                 %u / %u", kept, s.settings.maxStoredHits);
    if (offered > kept) ImGui::TextColored(ImVec4(1, 0.4f, 0.3f, 1), "overflow: %u hits dropped (raise maxStoredHits)", offered - kept);
    else ImGui::Text("overflow                    none");
    ImGui::Text("spheres (second type)       %u", s.stats[kStatSpheres]);
    ImGui::Text("hit-sphere pairs gathered   %u", s.stats[kStatGatherHits]);
}

void settingsSection(ViewerState& s) {
    if (!ImGui::CollapsingHeader("Caustics settings", ImGuiTreeNodeFlags_DefaultOpen)) return;
    CausticsSettings& c = s.settings;
    bool changed = false;
    int mapResolution = int(c.mapResolution);
    if (ImGui::SliderInt("map resolution", &mapResolution, 16, 2048, "%d", ImGuiSliderFlags_Logarithmic))
        c.mapResolution = uint32_t(mapResolution), changed = true;
    changed |= ImGui::SliderFloat("rays per texel", &c.raysPerTexel, 0.01f, 16.0f, "%.2f", ImGuiSliderFlags_Logarithmic);
    int depth = int(c.maxSpecularDepth);
    if (ImGui::SliderInt("max specular depth", &depth, 1, int(CausticsSettings::kMaxSpecularDepth)))
        c.maxSpecularDepth = uint32_t(depth), changed = true;
    changed |= ImGui::Checkbox("Russian roulette", &c.russianRoulette);
    changed |= ImGui::Checkbox("caustics", &c.causticsEnabled);
    ImGui::SameLine();
    changed |= ImGui::Checkbox("second type", &c.secondType);
    int policy = c.sphereRadiusPolicy == SphereRadiusPolicy::PixelFootprint ? 0 : 1;
    if (ImGui::Combo("sphere radius", &policy, "pixel footprint\0fixed world\0"))
        c.sphereRadiusPolicy = policy == 0 ? SphereRadiusPolicy::PixelFootprint : SphereRadiusPolicy::FixedWorld, changed = true;
    if (c.sphereRadiusPolicy == SphereRadiusPolicy::PixelFootprint)
        changed |= ImGui::SliderFloat("radius (footprints)", &c.sphereRadiusScale, 0.25f, 16.0f, "%.2f");
    else
        changed |= ImGui::SliderFloat("radius (m)", &c.sphereWorldRadius, 1e-4f, 1.0f, "%.4f", ImGuiSliderFlags_Logarithmic);
    if (c.sphereRadiusPolicy == SphereRadiusPolicy::PixelFootprint && ImGui::TreeNode("footprint clamps")) {
        changed |= ImGui::SliderFloat("min magnification", &c.sphereMinMagnification, 1e-3f, 1.0f, "%.4f", ImGuiSliderFlags_Logarithmic);
        changed |= ImGui::SliderFloat("max magnification", &c.sphereMaxMagnification, 1.0f, 256.0f, "%.1f", ImGuiSliderFlags_Logarithmic);
        ImGui::TreePop();
    }
    changed |= ImGui::SliderFloat("min radius (m)", &c.sphereMinRadius, 1e-6f, 0.1f, "%.2e", ImGuiSliderFlags_Logarithmic);
    changed |= ImGui::SliderFloat("max radius (m)", &c.sphereMaxRadius, 1e-3f, 10.0f, "%.3f", ImGuiSliderFlags_Logarithmic);
    int hits = int(std::min<uint32_t>(c.maxStoredHits, 1u << 26));
    if (ImGui::SliderInt("max stored hits", &hits, 1024, int(CausticsSettings::kMaxStoredHits), "%d", ImGuiSliderFlags_Logarithmic))
        c.maxStoredHits = uint32_t(hits), changed = true;
    changed |= ImGui::Checkbox("filter", &c.filter);
    if (c.filter) {
        int history = int(c.filterMaxHistory);
        if (ImGui::SliderInt("max history (frames)", &history, 1, 256, "%d", ImGuiSliderFlags_Logarithmic))
            c.filterMaxHistory = uint32_t(history), changed = true;
        int iterations = int(c.atrousIterations);
        if (ImGui::SliderInt("a-trous iterations", &iterations, 0, int(CausticsSettings::kMaxAtrousIterations)))
            c.atrousIterations = uint32_t(iterations), changed = true;
        changed |= ImGui::SliderFloat("luminance sigma", &c.filterLuminanceSigma, 0.25f, 16.0f, "%.2f", ImGuiSliderFlags_Logarithmic);
        if (c.secondType) changed |= ImGui::Checkbox("second type apart (own guides)", &c.filterSecondTypeApart);
    }
    changed |= ImGui::SliderFloat("exposure", &c.exposure, 1e-3f, 1e3f, "%.3f", ImGuiSliderFlags_Logarithmic);
    int seed = int(c.seed);
    if (ImGui::InputInt("seed", &seed) && seed >= 0) c.seed = uint32_t(seed), changed = true;
    int aov = int(c.aov);
    int framesInFlight = int(c.framesInFlight);
    if (ImGui::SliderInt("frames in flight (rebuilds)", &framesInFlight, 1, int(CausticsSettings::kMaxFramesInFlight)))
        c.framesInFlight = uint32_t(framesInFlight), changed = true;
    if (ImGui::Combo("AOV", &aov, "final\0direct\0caustics\0first type\0second type\0albedo\0normal\0depth\0"))
        c.aov = CausticsAov(aov), changed = true;
    s.settingsChanged |= changed;
}

void lightsSection(ViewerState& s) {
    if (!ImGui::CollapsingHeader("Lights")) return;
    for (size_t i = 0; i < s.lights.size(); ++i) {
        scene::Light& l = s.lights[i];
        ImGui::PushID(int(i));
        const char* type = l.type == scene::LightType::Point ? "point" : l.type == scene::LightType::Spot ? "spot" : "directional";
        if (ImGui::TreeNode("light", "%zu %s (%s)", i, l.name.c_str(), type)) {
            bool edited = false;
            if (l.type != scene::LightType::Directional) edited |= ImGui::DragFloat3("position", &l.position.x, 0.01f);
            if (l.type != scene::LightType::Point) {
                float yaw = std::atan2(l.direction.x, -l.direction.z) * kDegrees;
                float pitch = std::asin(std::clamp(l.direction.y, -1.0f, 1.0f)) * kDegrees;
                bool turned = ImGui::SliderFloat("yaw", &yaw, -180.0f, 180.0f, "%.1f deg");
                turned |= ImGui::SliderFloat("pitch", &pitch, -90.0f, 90.0f, "%.1f deg");
                if (turned) {
                    float y = yaw / kDegrees, p = pitch / kDegrees;
                    l.direction = {std::cos(p) * std::sin(y), std::sin(p), -std::cos(p) * std::cos(y)};
                    edited = true;
                }
            }
            edited |= ImGui::SliderFloat("intensity", &l.intensity, 0.0f, 1e6f, "%.3g", ImGuiSliderFlags_Logarithmic);
            edited |= ImGui::ColorEdit3("colour", &l.color.x);
            if (l.type == scene::LightType::Spot) {
                float inner = l.innerConeAngle * kDegrees, outer = l.outerConeAngle * kDegrees;
                edited |= ImGui::SliderFloat("inner cone", &inner, 0.0f, outer, "%.1f deg");
                edited |= ImGui::SliderFloat("outer cone", &outer, inner, 90.0f, "%.1f deg");
                l.innerConeAngle = inner / kDegrees;
                l.outerConeAngle = outer / kDegrees;
            }
            s.lightsChanged |= edited;   // live: no rebuild, so it follows the slider while dragged
            ImGui::TreePop();
        }
        ImGui::PopID();
    }
}

void animateSection(ViewerState& s) {
    if (!ImGui::CollapsingHeader("Animate", ImGuiTreeNodeFlags_DefaultOpen)) return;
    AnimationToggles& a = s.animation;
    char label[96];
    std::snprintf(label, sizeof(label), "glass objects move (%zu)", s.glassCount);
    ImGui::Checkbox(label, &a.objects);
    for (size_t i = 0; i < s.lights.size(); ++i) {
        bool orbit = a.orbitingLights.count(uint32_t(i)) != 0;
        std::snprintf(label, sizeof(label), "orbit: %zu %s", i, s.lights[i].name.c_str());
        if (ImGui::Checkbox(label, &orbit)) {
            if (orbit) a.orbitingLights.insert(uint32_t(i));
            else a.orbitingLights.erase(uint32_t(i));
        }
    }
    ImGui::SliderFloat("speed", &a.speed, 0.05f, 20.0f, "%.2f", ImGuiSliderFlags_Logarithmic);
    ImGui::Checkbox("pause", &a.paused);
    ImGui::SameLine();
    ImGui::TextDisabled("clocks: glass %.2f s, lights %.2f s", double(s.objectSeconds), double(s.lightSeconds));
}

void cameraSection(ViewerState& s, ViewerCamera& camera) {
    if (!ImGui::CollapsingHeader("Camera", ImGuiTreeNodeFlags_DefaultOpen)) return;
    int mode = camera.mode() == CameraMode::Orbit ? 0 : 1;
    if (ImGui::RadioButton("orbit", &mode, 0)) camera.setMode(CameraMode::Orbit);
    ImGui::SameLine();
    if (ImGui::RadioButton("fly", &mode, 1)) camera.setMode(CameraMode::Fly);
    ImGui::SameLine();
    if (ImGui::Button("reset")) camera.reset();
    ImGui::SliderFloat("fly speed (m/s)", &camera.speed, 1e-3f, 1e3f, "%.3f", ImGuiSliderFlags_Logarithmic);
    if (!s.sceneCameras.empty()) {
        int index = s.sceneCameraIndex;
        if (ImGui::SliderInt("glTF camera", &index, 0, int(s.sceneCameras.size()) - 1)) {
            s.sceneCameraIndex = index;
            camera.setView(s.sceneCameras[size_t(index)]);
        }
    }
    ImGui::TextDisabled("right drag: look/orbit  WASD QE: fly  wheel: dolly/speed");
    ImGui::TextDisabled("C: orbit/fly  R: reset  G: next glTF camera  F12: screenshot");
    ImGui::TextDisabled("M: move glass  O: orbit light 0  P: pause animation");
    ImGui::TextDisabled("Tab: hide panel  Esc: quit");
}

}  // namespace

void drawViewerPanel(ViewerState& s, ViewerCamera& camera) {
    ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(330, 0), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowBgAlpha(0.85f);
    ImGui::Begin("caustics");
    ImGui::Text("%s  %ux%u  frame %u", s.sceneName.c_str(), s.width, s.height, s.frame);
    ImGui::TextDisabled("%s", s.deviceName.c_str());
    timingSection(s);
    countersSection(s);
    settingsSection(s);
    lightsSection(s);
    animateSection(s);
    cameraSection(s, camera);
    if (!s.lastMessage.empty()) ImGui::TextWrapped("%s", s.lastMessage.c_str());
    ImGui::End();
}

}  // namespace caustics::sample
