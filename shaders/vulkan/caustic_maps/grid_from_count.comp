#version 460
// The grid of an indirect ray dispatch from a GPU counter: (min(counter, cap), 1, 1), or 0 launches when
// the gate counter is 0. caustics.gather is dispatched from the stored-hit count this way, gated by the
// sphere count, so its cost follows the stored hits and the spheres instead of
// CausticsSettings::maxStoredHits (docs/caustics.md, "Cost that follows the caustic work").
layout(local_size_x = 1) in;

layout(set = 0, binding = 0, std430) readonly buffer Counters { uint counters[]; };
layout(set = 0, binding = 1, std430) writeonly buffer Grid { uint grid[]; };
layout(push_constant) uniform Push { uint slot; uint cap; uint gateSlot; } pc;

void main() {
    grid[0] = counters[pc.gateSlot] == 0u ? 0u : min(counters[pc.slot], pc.cap);
    grid[1] = 1u;
    grid[2] = 1u;
}
