#pragma once
// Chooses the scene the sample renders: a built-in one, any glTF file, or "modified Sponza" (a glTF
// plus the caustic objects and lights).
#include <string>

#include "cli_options.h"
#include "caustics/scene/scene.h"

namespace caustics::sample {

Result<scene::Scene> loadSceneFromOptions(const CliOptions& options);

}  // namespace caustics::sample
