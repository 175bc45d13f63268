#pragma once
// The viewer's Dear ImGui panel: timings (medians and history plots), caustic counters, every
// CausticsSettings field, the lights and the camera. It only edits ViewerState; the loop applies.
#include "viewer_state.h"

namespace caustics::sample {

void drawViewerPanel(ViewerState& state, ViewerCamera& camera);

}  // namespace caustics::sample
