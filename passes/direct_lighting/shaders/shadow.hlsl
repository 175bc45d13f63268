// D3D12 miss of direct_lighting's shadow rays (shadow.rmiss).
#include "direct_light.h"
[shader("miss")]
void main(inout ShadowPayload payload) { payload.unoccluded = 1u; }
