// The table scene after the paper's Figures 1-3 and the "Modified Sponza" placement. Layout in
// metres with the table top at y = 0; intensities in candela chosen for exposure 1: the caustic
// spot gives about 3 lx on the table (a white diffuse surface then has radiance ~0.8/pi * 3 ~ 0.8).
#include "caustics/scene/builtin_scenes.h"

#include <glm/gtc/matrix_transform.hpp>

#include "caustics/rhi/log.h"
#include "caustics/scene/gltf.h"
#include "caustics/scene/mesh_builder.h"
#include "caustics/scene/mesh_utils.h"
#include "caustics/scene/procedural_textures.h"
#include "scene_build.h"

namespace caustics::scene {

using namespace build;

Scene makeAtriumScene();   // builtin_atrium.cpp

size_t addCausticObjects(Scene& scene, const CausticPlacement& p) {
    const float s = p.scale;
    auto at = [&](float x, float y, float z) {
        return glm::translate(glm::mat4(1.0f), p.origin + s * glm::vec3(x, y, z)) * glm::scale(glm::mat4(1.0f), glm::vec3(s));
    };
    // Glass of water: a closed thick-walled shell (4 mm walls, 8 mm base) and, inside it, a water
    // cylinder kept 0.5 mm off the glass so no two surfaces coincide (coplanar hits are ambiguous).
    uint32_t glass = addMaterial(scene, dielectric("glass (IOR 1.5)", 1.5f, 0.004f * s));
    uint32_t water = addMaterial(scene, dielectric("water (IOR 1.33)", 1.33f, 0.07f * s, {0.90f, 0.96f, 1.0f}, 2.0f * s));
    uint32_t steel = addMaterial(scene, metal("polished metal", {0.95f, 0.93f, 0.88f}, 0.02f));
    addObject(scene, makeTube(0.040f, 0.036f, 0.12f, 128, 0.008f), glass, "glass", at(-0.14f, 0.0f, 0.02f));
    addObject(scene, makeCylinder(0.0355f, 0.0815f, 128, 1, true), water, "water", at(-0.14f, 0.0085f, 0.02f));
    addObject(scene, makeSphere(0.05f, 96, 48), glass, "glass sphere", at(0.04f, 0.05f, 0.08f));
    // The ring stands upright on its rim: its inner wall focuses the cardioid (a nephroid-like
    // catacaustic of a circle lit from the side).
    addObject(scene, makeTube(0.050f, 0.047f, 0.03f, 128, 0.0f), steel, "metal ring", at(0.20f, 0.0f, -0.05f));

    size_t firstLight = scene.lights.size();
    if (p.addLights) {
        const float area = s * s;   // keeps the illuminance when the whole layout is scaled
        glm::vec3 focus = p.origin + s * glm::vec3(0.0f, 0.04f, 0.0f);
        scene.lights.push_back(spotLight("caustic spot (side-front)", p.origin + s * glm::vec3(-0.55f, 0.30f, 0.45f), focus,
                                         3.0f * area, 0.30f, 0.42f, {1.0f, 0.95f, 0.85f}));
        Light point;
        point.name = "caustic point (right-front)";
        point.type = LightType::Point;
        point.position = p.origin + s * glm::vec3(0.45f, 0.35f, 0.35f);
        point.intensity = 1.5f * area;
        point.color = {0.9f, 0.95f, 1.0f};
        scene.lights.push_back(point);
        // Sees no specular object (aimed away from them): the passes skip it (paper, Figure 3).
        scene.lights.push_back(spotLight("wall corner spot (no caustics)", p.thirdLightPosition, p.thirdLightTarget,
                                         2.0f * area, 0.10f, 0.15f));
    }
    return firstLight;
}

static Scene makeTableScene() {
    Scene scene;
    scene.name = "table (builtin)";
    uint32_t woodTex = addTexture(scene, makeWoodTexture(128, {0.62f, 0.45f, 0.30f}, {0.40f, 0.26f, 0.15f}, 7), "wood");
    uint32_t wallTex = addTexture(scene, makeNoiseTexture(64, {0.75f, 0.74f, 0.70f}, 0.15f, 3), "plaster");
    uint32_t table = addMaterial(scene, diffuse("table top", glm::vec3(1.0f), int32_t(woodTex), 0.7f));
    uint32_t wall = addMaterial(scene, diffuse("back wall", glm::vec3(1.0f), int32_t(wallTex), 0.9f));
    addObject(scene, makeBox({0.6f, 0.02f, 0.4f}, 1.5f), table, "table top",
              glm::translate(glm::mat4(1.0f), {0.0f, -0.02f, 0.0f}));
    addObject(scene, makeBox({0.8f, 0.55f, 0.01f}, 1.0f), wall, "back wall",
              glm::translate(glm::mat4(1.0f), {0.0f, 0.5f, -0.42f}));
    CausticPlacement placement;
    placement.thirdLightPosition = {-0.45f, 0.9f, -0.05f};
    placement.thirdLightTarget = {-0.75f, 0.8f, -0.41f};   // the wall's upper-left corner
    addCausticObjects(scene, placement);
    scene.cameras.push_back(lookAt({0.0f, 0.35f, 0.75f}, {0.02f, 0.04f, 0.0f}, glm::radians(40.0f)));
    scene.exposure = 1.0f;
    sortTrianglesMorton(scene);
    return scene;
}

std::vector<std::string> builtinSceneNames() { return {"builtin", "builtin:table", "builtin:atrium", "builtin:level"}; }

Result<Scene> makeBuiltin(const std::string& name) {
    if (name == "builtin" || name == "builtin:table") return makeTableScene();
    if (name == "builtin:atrium") return makeAtriumScene();
    if (name == "builtin:level") return makeLevelScene();
    return makeError("unknown built-in scene '" + name + "' (known: builtin, builtin:table, builtin:atrium, builtin:level)");
}

Scene makeBuiltinScene(const std::string& name) {
    Result<Scene> scene = makeBuiltin(name);
    if (scene) return std::move(scene).value();
    log(LogLevel::Warning, scene.message() + "; using builtin:table");
    return makeTableScene();
}

Result<Scene> loadModifiedSponza(const std::string& gltfPath, const LoadOptions& options) {
    CAUSTICS_TRY(Scene scene, loadGltf(gltfPath, options));
    Aabb box = sceneBounds(scene);
    if (box.empty()) return makeError(gltfPath + ": the scene has no geometry to place the caustic objects in");
    glm::vec3 e = box.extent(), c = box.center();
    float horizontal = std::min(e.x, e.z);
    if (!(horizontal > 0.0f)) return makeError(gltfPath + ": the scene is flat in x or z; cannot place the caustic objects");
    CausticPlacement p;
    p.origin = {c.x, box.min.y, c.z};   // centre of the floor
    p.scale = horizontal / 3.0f;        // Sponza's ~12 m courtyard -> a ~0.5 m glass
    p.thirdLightPosition = {c.x - 0.2f * e.x, box.min.y + 0.7f * e.y, c.z - 0.2f * e.z};
    p.thirdLightTarget = {box.min.x + 0.02f * e.x, box.min.y + 0.9f * e.y, box.min.z + 0.02f * e.z};
    addCausticObjects(scene, p);
    for (size_t i = 0; i < scene.instances.size(); ++i) scene.instances[i].objectId = uint32_t(i + 1);
    scene.cameras.insert(scene.cameras.begin(),
                         lookAt(p.origin + p.scale * glm::vec3(0.0f, 0.35f, 0.75f), p.origin + p.scale * glm::vec3(0.02f, 0.04f, 0.0f),
                                glm::radians(50.0f)));
    scene.name += " (modified: caustic objects added)";
    for (Mesh& mesh : scene.meshes) sortTrianglesMorton(mesh);
    return scene;
}

}  // namespace caustics::scene
