#pragma once
// Scenes of the benchmark: a built-in scene (generated stand-ins, labelled as such) with optional
// extra caustic lights, and the two camera views of the paper's Figure 9 (the caustic lights' work
// visible to the camera, or the camera turned away so that none of it is on screen).
#include <cstdint>
#include <string>

#include "caustics/rhi/result.h"
#include "caustics/scene/scene.h"

namespace caustics::bench {

// Adds `count` spot lights on a ring above the specular objects, each aimed at their bounding sphere
// (so each forms its own caustic map), copying the colour and intensity of the scene's first spot.
void addRingLights(scene::Scene& scene, uint32_t count);

enum class BenchView { Visible, Away };
const char* viewName(BenchView view);

// The scene's first camera, or the same eye looking the opposite way.
scene::Camera benchCamera(const scene::Scene& scene, BenchView view);

Result<scene::Scene> loadBenchScene(const std::string& name, uint32_t extraLights);

}  // namespace caustics::bench
