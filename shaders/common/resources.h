#ifndef CAUSTICS_COMMON_RESOURCES_H
#define CAUSTICS_COMMON_RESOURCES_H
// Resource access in the shared dialect (docs/shaders.md): the few texture reads and writes a pass
// body's thread function makes, one spelling per API. The resources themselves are declared by the
// generated bindings/<pass>.glsl / .hlsl (shaders/bindings/); storage buffers are read and written
// through the generated <name>Load / <name>Store accessors. Not in the C++ branch: C++ type-checks
// the pure functions of a body, which take and return values.
#include "common/lang.h"

#if defined(CAUSTICS_LANG_HLSL)
#define CAUSTICS_TEXEL(tex, p) (tex).Load(int3((p), 0))
#define CAUSTICS_TEXEL_UINT(tex, p) (tex).Load(int3((p), 0))
#define CAUSTICS_TEXEL_ARRAY_UINT(tex, p, layer) (tex).Load(int4((p), (layer), 0))
#define CAUSTICS_IMAGE_STORE(img, p, v) (img)[(p)] = (v)
#define CAUSTICS_IMAGE_STORE_UINT(img, p, u) (img)[(p)] = (u)
#define CAUSTICS_IMAGE_LOAD(img, p) (img)[(p)]
#define CAUSTICS_IMAGE_LOAD_UINT(img, p) (img)[(p)]
#elif defined(CAUSTICS_LANG_GLSL)
#define CAUSTICS_TEXEL(tex, p) texelFetch((tex), (p), 0)
#define CAUSTICS_TEXEL_UINT(tex, p) texelFetch((tex), (p), 0).r
#define CAUSTICS_TEXEL_ARRAY_UINT(tex, p, layer) texelFetch((tex), ivec3((p), (layer)), 0).r
#define CAUSTICS_IMAGE_STORE(img, p, v) imageStore((img), (p), (v))
#define CAUSTICS_IMAGE_STORE_UINT(img, p, u) imageStore((img), (p), uvec4(u))
#define CAUSTICS_IMAGE_LOAD(img, p) imageLoad((img), (p))
#define CAUSTICS_IMAGE_LOAD_UINT(img, p) imageLoad((img), (p)).r
#endif

#endif  // CAUSTICS_COMMON_RESOURCES_H
