#ifndef CAUSTICS_COMMON_TONE_MAP_H
#define CAUSTICS_COMMON_TONE_MAP_H
// Display transform of the composite pass (and of the sample's --accumulate stills, which average
// linear frames on the host and must tone-map exactly as the GPU does): the ACES filmic fit of
// Narkowicz 2015, x (2.51 x + 0.03) / (x (2.43 x + 0.59) + 0.14), then the sRGB encoding
// (IEC 61966-2-1).
#include "common/lang.h"

CAUSTICS_SHARED_BEGIN

// The fit is white (>= 0.999) from x = 60 on; clamping its input at 1e4 keeps x * x finite for any
// radiance up to float's limit, so a 1e38 cd light (or inf from an RGBA16F overflow) shows white
// instead of the black that inf / inf = NaN gave.
CAUSTICS_CONST float kToneInputLimit = 1.0e4f;

CAUSTICS_FN float3 acesFitted(float3 x) {
    x = clamp(x, splat3(0.0f), splat3(kToneInputLimit));
    return saturate((x * (2.51f * x + 0.03f)) / (x * (2.43f * x + 0.59f) + 0.14f));
}

CAUSTICS_FN float srgbEncodeChannel(float c) {
    c = saturate(c);
    return c < 0.0031308f ? 12.92f * c : 1.055f * pow(c, 1.0f / 2.4f) - 0.055f;
}

CAUSTICS_FN float3 srgbEncode(float3 c) {
    return float3(srgbEncodeChannel(c.x), srgbEncodeChannel(c.y), srgbEncodeChannel(c.z));
}

CAUSTICS_SHARED_END

#endif  // CAUSTICS_COMMON_TONE_MAP_H
