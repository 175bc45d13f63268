// "level (game-level stand-in, generated)": a square courtyard the size of a game level with specular
// objects of every kind spread over it (glass balls, glass windows, water basins, metal rings and
// plates), diffuse walls and plinths as receivers, a sun and street lamps (spot) and lanterns (point)
// with a range, as a level's lights have. It exercises what a table top cannot: caustics far apart,
// most of them out of view (docs/caustics.md, "Layers per cluster" and "Photon budget").
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "caustics/scene/builtin_scenes.h"
#include "caustics/scene/mesh_builder.h"
#include "caustics/scene/mesh_utils.h"
#include "scene_build.h"

namespace caustics::scene {

using namespace build;

namespace {

glm::mat4 translate(glm::vec3 p) { return glm::translate(glm::mat4(1.0f), p); }

// A small deterministic generator (the same level on every machine): 32-bit LCG (Numerical Recipes).
struct Lcg {
    uint32_t state;
    float next() {
        state = state * 1664525u + 1013904223u;
        return float(state >> 8) * (1.0f / 16777216.0f);
    }
    float range(float lo, float hi) { return lo + (hi - lo) * next(); }
};

}  // namespace

Scene makeLevelScene(const LevelSceneDesc& desc) {
    Scene scene;
    scene.name = "level (game-level stand-in, generated)";
    scene.isStandIn = true;
    const float half = 0.5f * desc.extent;
    uint32_t ground = addMaterial(scene, diffuse("paving", glm::vec3(0.55f, 0.52f, 0.48f), -1, 0.9f));
    uint32_t stone = addMaterial(scene, diffuse("stone", glm::vec3(0.7f, 0.66f, 0.6f), -1, 0.85f));
    uint32_t glass = addMaterial(scene, dielectric("glass (IOR 1.5)", 1.5f, 0.5f));
    uint32_t pane = addMaterial(scene, dielectric("window glass (IOR 1.5)", 1.5f, 0.02f));
    uint32_t water = addMaterial(scene, dielectric("water (IOR 1.33)", 1.33f, 0.3f, {0.85f, 0.95f, 1.0f}, 6.0f));
    uint32_t steel = addMaterial(scene, metal("polished metal", {0.95f, 0.93f, 0.88f}, 0.02f));
    uint32_t brass = addMaterial(scene, metal("brass", {0.95f, 0.78f, 0.45f}, 0.05f));
    addObject(scene, makePlane(half, half, 64, 0.25f), ground, "courtyard floor");

    // Objects on a jittered grid over the court, the kinds in turn; each stands by a wall or on a
    // plinth so its caustic falls on something near it.
    Lcg rng{desc.seed * 2654435761u + 1u};
    const uint32_t n = std::max(desc.objects, 1u);
    const uint32_t side = uint32_t(std::ceil(std::sqrt(float(n))));
    const float cell = desc.extent / float(side);
    for (uint32_t i = 0; i < n; ++i) {
        const float cx = -half + cell * (float(i % side) + rng.range(0.3f, 0.7f));
        const float cz = -half + cell * (float(i / side) + rng.range(0.3f, 0.7f));
        const glm::vec3 at(cx, 0.0f, cz);
        const float turn = rng.range(0.0f, 6.2831853f);
        const glm::mat4 turned = translate(at) * glm::rotate(glm::mat4(1.0f), turn, {0, 1, 0});
        // A wall 2 m behind each object catches reflected and refracted light.
        addObject(scene, makeBox({2.0f, 1.5f, 0.15f}), stone, "wall " + std::to_string(i),
                  turned * translate({0.0f, 1.5f, -2.0f}));
        switch (i % 5) {
            case 0: {   // glass ball on a plinth
                const float r = rng.range(0.3f, 0.6f);
                addObject(scene, makeBox({0.4f, 0.4f, 0.4f}), stone, "plinth " + std::to_string(i), turned * translate({0, 0.4f, 0}));
                addObject(scene, makeSphere(r, 64, 32), glass, "glass ball " + std::to_string(i),
                          turned * translate({0.0f, 0.8f + r + 0.6f, 0.0f}));
                break;
            }
            case 1:   // a standing window pane
                addObject(scene, makeBox({0.8f, 1.0f, 0.02f}), pane, "window " + std::to_string(i), turned * translate({0, 1.4f, 0}));
                break;
            case 2: {   // a water basin: stone rim, water surface slab
                addObject(scene, makeTube(1.2f, 1.1f, 0.4f, 64, 0.1f), stone, "basin " + std::to_string(i), turned);
                addObject(scene, makeCylinder(1.09f, 0.28f, 64, 1, true), water, "water " + std::to_string(i),
                          turned * translate({0, 0.1f, 0}));
                break;
            }
            case 3:   // a polished ring on the ground
                addObject(scene, makeTube(0.6f, 0.57f, 0.3f, 96, 0.0f), steel, "metal ring " + std::to_string(i), turned);
                break;
            default:   // a brass plate leaning on its wall: a mirror throwing the sun on the ground
                addObject(scene, makeBox({0.6f, 0.6f, 0.02f}), brass, "brass plate " + std::to_string(i),
                          turned * translate({0, 0.9f, -1.2f}) * glm::rotate(glm::mat4(1.0f), 0.5f, {1, 0, 0}));
                break;
        }
    }

    // A low sun (lux), 8 street lamps (spots aimed at objects) and 8 lanterns (points), both with a
    // range of 15 m as a level's lights have, spread over the court.
    Light sun;
    sun.name = "sun";
    sun.type = LightType::Directional;
    sun.direction = glm::normalize(glm::vec3(0.45f, -0.8f, 0.3f));
    sun.intensity = desc.sunIlluminance;
    sun.color = {1.0f, 0.96f, 0.9f};
    scene.lights.push_back(sun);
    for (uint32_t k = 0; k < 16; ++k) {
        const uint32_t target = (k * 7 + 3) % n;
        const float tx = -half + cell * (float(target % side) + 0.5f), tz = -half + cell * (float(target / side) + 0.5f);
        const glm::vec3 aim(tx, 0.5f, tz);
        const glm::vec3 pos = aim + glm::vec3(rng.range(-3.0f, 3.0f), 6.0f, rng.range(-3.0f, 3.0f));
        if (k < 8) {
            Light spot = spotLight("street lamp " + std::to_string(k), pos, aim, 400.0f, 0.35f, 0.6f, {1.0f, 0.9f, 0.75f});
            spot.range = 15.0f;
            scene.lights.push_back(spot);
        } else {
            Light lantern;
            lantern.name = "lantern " + std::to_string(k - 8);
            lantern.type = LightType::Point;
            lantern.position = pos - glm::vec3(0.0f, 3.0f, 0.0f);
            lantern.intensity = 150.0f;
            lantern.color = {1.0f, 0.85f, 0.6f};
            lantern.range = 15.0f;
            scene.lights.push_back(lantern);
        }
    }
    // The default camera stands in one corner of the court, looking over its first objects.
    const glm::vec3 first(-half + 0.5f * cell, 0.0f, -half + 0.5f * cell);
    scene.cameras.push_back(lookAt(first + glm::vec3(6.0f, 4.0f, 7.0f), first + glm::vec3(0.0f, 0.8f, 0.0f), glm::radians(50.0f)));
    scene.cameras.back().farPlane = desc.extent * 1.5f;
    scene.exposure = 1.0f / std::max(desc.sunIlluminance, 1e-6f);
    sortTrianglesMorton(scene);
    return scene;
}

}  // namespace caustics::scene
