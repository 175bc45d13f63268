#ifndef CAUSTICS_COMMON_GROUP_SHARED_H
#define CAUSTICS_COMMON_GROUP_SHARED_H
// Group-shared memory in the shared dialect's GLSL and HLSL spellings (docs/shaders.md): the qualifier,
// the group barrier and the atomics on group-shared words that the compute bodies use (the filter's
// passes, caustics.specularPixels). GLSL and HLSL only.
#if !defined(CAUSTICS_LANG_CPP)
#if defined(CAUSTICS_LANG_HLSL)
#define CAUSTICS_GROUPSHARED groupshared
#define CAUSTICS_GROUP_BARRIER() GroupMemoryBarrierWithGroupSync()
#define CAUSTICS_GROUP_ATOMIC_OR(target, value) InterlockedOr(target, value)
#define CAUSTICS_GROUP_ATOMIC_MAX(target, value) InterlockedMax(target, value)
#else
#define CAUSTICS_GROUPSHARED shared
#define CAUSTICS_GROUP_BARRIER() barrier()
#define CAUSTICS_GROUP_ATOMIC_OR(target, value) atomicOr(target, value)
#define CAUSTICS_GROUP_ATOMIC_MAX(target, value) atomicMax(target, value)
#endif
#endif  // !CAUSTICS_LANG_CPP

#endif  // CAUSTICS_COMMON_GROUP_SHARED_H
