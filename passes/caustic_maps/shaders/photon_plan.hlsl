// D3D12 entry of caustics.photonPlan; the body is photon_plan.h (docs/shaders.md).
#include "photon_plan.h"
[numthreads(1, 1, 1)]
void main() { planPhotons(params); }
