// The grid of an indirect ray dispatch from a GPU counter (mirror of
// shaders/vulkan/caustic_maps/grid_from_count.comp): (min(counter, cap), 1, 1).
ByteAddressBuffer counters : register(t0, space0);
RWByteAddressBuffer grid : register(u1, space0);
struct Push { uint slot; uint cap; };
ConstantBuffer<Push> pc : register(b0, space999);

[numthreads(1, 1, 1)]
void main() {
    grid.Store3(0u, uint3(min(counters.Load(4u * pc.slot), pc.cap), 1u, 1u));
}
