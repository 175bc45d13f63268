#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_ray_tracing : require
// Miss of every scene trace (forward.h traceScene): t < 0.
#include "common/caustic_hit.h"
layout(location = 0) rayPayloadInEXT TracePayload payload;
void main() { payload.t = -1.0; }
