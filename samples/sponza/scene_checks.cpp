#include "scene_checks.h"

#include "caustics/caustic_map_plan.h"

namespace caustics::sample {

scene::Light defaultSunLight() {
    scene::Light sun;
    sun.name = "default sun";
    sun.type = scene::LightType::Directional;
    sun.direction = glm::normalize(glm::vec3(-0.3f, -1.0f, -0.4f));
    // 3 lux on a Lambertian albedo of 0.8 gives 0.76 cd/m^2 (L = albedo E / pi), mid-grey after the
    // ACES curve at exposure 1: a neutral default for a file that carries no lights of its own.
    sun.intensity = 3.0f;
    return sun;
}

std::vector<std::string> prepareSceneForRendering(scene::Scene& s) {
    std::vector<std::string> warnings;
    if (s.lights.empty()) {
        scene::Light sun = defaultSunLight();
        s.lights.push_back(sun);
        warnings.push_back("scene '" + s.name + "' has no lights; added a default directional light '" + sun.name +
                           "' (3 lux, shining down along (-0.3, -1, -0.4)). To light it yourself, add "
                           "KHR_lights_punctual lights to the glTF (Blender's glTF exporter writes them with "
                           "'Punctual Lights' checked)");
    }
    if (s.lights.size() > kMaxCausticLights) {
        std::string names;
        for (size_t l = kMaxCausticLights; l < s.lights.size(); ++l) {
            if (l - kMaxCausticLights == 8) {
                names += ", ... (" + std::to_string(s.lights.size() - l) + " more)";
                break;
            }
            names += (names.empty() ? "" : ", ") + std::to_string(l) + " '" + s.lights[l].name + "'";
        }
        warnings.push_back("scene '" + s.name + "' has " + std::to_string(s.lights.size()) + " lights; only the first " +
                           std::to_string(kMaxCausticLights) + " (kMaxCausticLights) form caustics. Lights without "
                           "caustics: " + names);
    }
    return warnings;
}

}  // namespace caustics::sample
