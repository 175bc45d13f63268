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

// Adds `count` spot lights on the same ring, each aimed straight away from the specular objects, so that
// no cone contains a specular instance and the map planner culls them (caustic_map_plan.cpp): the
// "culled" series of the lights sweep measures what such a light still costs.
void addCulledRingLights(scene::Scene& scene, uint32_t count);

enum class BenchView { Visible, Away };
const char* viewName(BenchView view);

// The scene's first camera, or the same eye looking the opposite way.
scene::Camera benchCamera(const scene::Scene& scene, BenchView view);

// World-space box around every instance of the scene (the incoherent rays' origins in the sweep).
void sceneBox(const scene::Scene& scene, float boxMin[3], float boxMax[3]);

Result<scene::Scene> loadBenchScene(const std::string& name, uint32_t extraLights, uint32_t culledLights = 0);

}  // namespace caustics::bench
