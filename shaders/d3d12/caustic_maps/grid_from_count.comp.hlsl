// The grid of an indirect ray dispatch from a GPU counter (mirror of
// shaders/vulkan/caustic_maps/grid_from_count.comp): (min(counter, cap), 1, 1),
// 0 launches when the gate counter is 0.
ByteAddressBuffer counters : register(t0, space0);
RWByteAddressBuffer grid : register(u1, space0);
struct Push { uint slot; uint cap; uint gateSlot; };
ConstantBuffer<Push> pc : register(b0, space999);

[numthreads(1, 1, 1)]
void main() {
    uint launches = counters.Load(4u * pc.gateSlot) == 0u ? 0u : min(counters.Load(4u * pc.slot), pc.cap);
    grid.Store3(0u, uint3(launches, 1u, 1u));
}
