// Small analytic scenes for the physics tests: one specular object, one diffuse plane y = 0, one
// directional light. Meshes are finely tessellated with smooth normals.
#include <glm/gtc/matrix_transform.hpp>

#include "caustics/scene/builtin_scenes.h"
#include "caustics/scene/mesh_builder.h"
#include "caustics/scene/mesh_utils.h"
#include "scene_build.h"

namespace caustics::scene {

using namespace build;

static Scene makePlaneScene(const std::string& name, const AnalyticSceneDesc& d) {
    Scene scene;
    scene.name = name;
    // A Lambertian receiver: KHR_materials_specular factor 0 leaves no specular layer in the shared
    // BRDF (shaders/common/bsdf.h), so the physics tests' analytic radiance rho E / pi holds exactly.
    Material planeMaterial = diffuse("diffuse plane", glm::vec3(d.planeAlbedo), -1, 1.0f);
    planeMaterial.specular = 0.0f;
    uint32_t plane = addMaterial(scene, planeMaterial);
    addObject(scene, makePlane(d.planeHalfSize, d.planeHalfSize, 8), plane, "plane");
    Light sun;
    sun.name = "directional";
    sun.type = LightType::Directional;
    sun.direction = glm::normalize(d.lightDirection);
    sun.position = -10.0f * sun.direction;
    sun.intensity = d.lightIlluminance;
    scene.lights.push_back(sun);
    scene.cameras.push_back(lookAt({0.0f, 3.0f * std::max(d.height, 1.0f), 0.01f}, {0.0f, 0.0f, 0.0f}, glm::radians(60.0f)));
    return scene;
}

Scene makeGlassSphereScene(const AnalyticSceneDesc& d) {
    Scene scene = makePlaneScene("analytic: glass sphere", d);
    uint32_t glass = addMaterial(scene, dielectric("glass", d.ior, 2.0f * d.radius));
    addObject(scene, makeSphere(d.radius, d.tessellation, std::max(d.tessellation / 2, 3u)), glass, "glass sphere",
              glm::translate(glm::mat4(1.0f), {0.0f, d.height, 0.0f}));
    sortTrianglesMorton(scene);
    return scene;
}

Scene makeGlassSlabScene(const AnalyticSceneDesc& d) {
    Scene scene = makePlaneScene("analytic: glass slab", d);
    uint32_t glass = addMaterial(scene, dielectric("glass", d.ior, d.thickness));
    addObject(scene, makeBox({1.0f, 0.5f * d.thickness, 1.0f}), glass, "glass slab",
              glm::translate(glm::mat4(1.0f), {0.0f, d.height + 0.5f * d.thickness, 0.0f}));
    sortTrianglesMorton(scene);
    return scene;
}

Scene makeMetalRingScene(AnalyticSceneDesc d) {
    Scene scene = makePlaneScene("analytic: metal ring", d);
    uint32_t steel = addMaterial(scene, metal("polished metal", glm::vec3(0.95f), 0.0f));
    addObject(scene, makeTube(d.radius + d.thickness, d.radius, d.height, d.tessellation, 0.0f), steel, "metal ring");
    sortTrianglesMorton(scene);
    return scene;
}

}  // namespace caustics::scene
