#pragma once
// What the sample checks about a loaded scene before rendering it, so that a user gets a sentence
// instead of a black image: a scene without lights gets a default light, and lights beyond what the
// caustic passes can take (kMaxCausticLights) are named.
#include <string>
#include <vector>

#include "caustics/scene/scene.h"

namespace caustics::sample {

// The light added to a scene that has none (say which in the warning).
scene::Light defaultSunLight();

// Adjusts `scene` where needed and returns the warnings to print (one sentence each).
std::vector<std::string> prepareSceneForRendering(scene::Scene& scene);

}  // namespace caustics::sample
