#ifndef CAUSTICS_COMMON_LUMINANCE_H
#define CAUSTICS_COMMON_LUMINANCE_H
// Rec. 709 luminance of linear RGB (ITU-R BT.709 primaries, Y = 0.2126 R + 0.7152 G + 0.0722 B): the
// scalar the caustic filter's moments and differences are taken of (docs/caustics.md "Filter") and the
// second type's photon weights are measured in (docs/caustics.md "Second-type guides").
#include "common/lang.h"

CAUSTICS_SHARED_BEGIN
CAUSTICS_FN float rec709Luminance(float3 c) { return dot(c, float3(0.2126f, 0.7152f, 0.0722f)); }
CAUSTICS_SHARED_END

#endif  // CAUSTICS_COMMON_LUMINANCE_H
