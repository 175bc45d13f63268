#version 460
#extension GL_GOOGLE_include_directive : require
// Vulkan fragment entry of caustics.maps; the body is caustic_map.h (docs/shaders.md).
#define CAUSTIC_MAP_FRAGMENT
#include "caustic_map.h"
layout(location = 0) flat in uint inInstance;
layout(location = 0) out uint outObjectId;
void main() { outObjectId = causticMapObjectId(inInstance); }
