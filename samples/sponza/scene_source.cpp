#include "scene_source.h"

#include <cmath>

#include "caustics/scene/builtin_scenes.h"
#include "caustics/scene/gltf.h"

namespace caustics::sample {

Result<scene::Scene> loadSceneFromOptions(const CliOptions& o) {
    if (!o.sponzaPath.empty()) return scene::loadModifiedSponza(o.sponzaPath);
    if (o.scene == "builtin" || o.scene.rfind("builtin:", 0) == 0) return scene::makeBuiltin(o.scene);
    return scene::loadGltf(o.scene);
}

scene::Camera cameraFromOptions(const scene::Scene& s, const CliOptions& o) {
    scene::Camera camera;
    if (!s.cameras.empty()) camera = s.cameras.front();
    if (o.camera) {
        camera.eye = o.camera->eye;
        camera.target = o.camera->target;
        camera.verticalFovRadians = o.camera->verticalFovDegrees * 3.14159265f / 180.0f;
    }
    return camera;
}

}  // namespace caustics::sample
