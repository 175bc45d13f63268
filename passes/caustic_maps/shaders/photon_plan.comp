#version 460
#extension GL_GOOGLE_include_directive : require
// Vulkan entry of caustics.photonPlan; the body is photon_plan.h (docs/shaders.md).
#include "photon_plan.h"
layout(local_size_x = 1) in;
void main() { planPhotons(params); }
