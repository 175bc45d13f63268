#include "scene_source.h"

#include "caustics/scene/builtin_scenes.h"
#include "caustics/scene/gltf.h"

namespace caustics::sample {

Result<scene::Scene> loadSceneFromOptions(const CliOptions& o) {
    scene::LoadOptions options;
    options.assetRoot = o.assetRoot;
    if (!o.sponzaPath.empty()) return scene::loadModifiedSponza(o.sponzaPath, options);
    if (o.scene == "builtin" || o.scene.rfind("builtin:", 0) == 0) return scene::makeBuiltin(o.scene);
    return scene::loadGltf(o.scene, options);
}

}  // namespace caustics::sample
