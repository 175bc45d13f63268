#ifndef CAUSTICS_COMMON_VOLUME_H
#define CAUSTICS_COMMON_VOLUME_H
// Beer-Lambert absorption inside transmissive volumes (KHR_materials_volume): light that travels
// attenuationDistance through the medium keeps attenuationColor of its energy, so
// sigma_a = -ln(attenuationColor) / attenuationDistance and T(d) = exp(-sigma_a d).
#include "common/lang.h"

CAUSTICS_SHARED_BEGIN

// attenuationDistance <= 0 means "infinite" (the extension's default): no absorption.
CAUSTICS_FN float3 volumeSigmaA(float3 attenuationColor, float attenuationDistance) {
    if (attenuationDistance <= 0.0f) return splat3(0.0f);
    // Clamp so that a black attenuation colour gives a large, finite coefficient instead of +inf.
    float3 c = clamp(attenuationColor, 1.0e-6f, 1.0f);
    return -log(c) / attenuationDistance;
}

CAUSTICS_FN float3 beerLambert(float3 sigmaA, float distance) { return exp(-sigmaA * distance); }

CAUSTICS_SHARED_END

#endif  // CAUSTICS_COMMON_VOLUME_H
