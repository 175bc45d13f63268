#ifndef CAUSTICS_SPHERE_LIST_GLSL
#define CAUSTICS_SPHERE_LIST_GLSL
// Statistics slots of the second type's cost (mirror of caustic_passes.h; docs/caustics.md, "Second-type
// cost"): specular pixels compacted by caustics.specularPixels, launches of caustics.backward, spheres
// that found no slot below the sphere capacity, and that capacity.
const uint kStatSpecularPixels = 69u;
const uint kStatBackwardLaunches = 70u;
const uint kStatSpheresDropped = 71u;
const uint kStatSphereCapacity = 72u;
#endif
