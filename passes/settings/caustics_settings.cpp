#include "caustics/caustics_settings.h"

#include <cmath>
#include <sstream>

namespace caustics {
namespace {
template <typename T>
Error outOfRange(const char* field, T value, T lo, T hi) {
    std::ostringstream s;
    s << "CausticsSettings::" << field << " = " << value << " is outside [" << lo << ", " << hi << "]";
    return makeError(s.str());
}
}  // namespace

Status CausticsSettings::validate() const {
    if (mapResolution < 1 || mapResolution > kMaxMapResolution)
        return outOfRange("mapResolution", mapResolution, 1u, kMaxMapResolution);
    if (!std::isfinite(raysPerTexel) || raysPerTexel <= 0.0f || raysPerTexel > kMaxRaysPerTexel)
        return makeError("CausticsSettings::raysPerTexel = " + std::to_string(raysPerTexel) +
                         " must be greater than 0 and at most " + std::to_string(kMaxRaysPerTexel));
    if (photonsPerFrame > kMaxPhotonsPerFrame)
        return outOfRange("photonsPerFrame", photonsPerFrame, 0u, kMaxPhotonsPerFrame);
    if (!std::isfinite(causticTimeTargetMs) || causticTimeTargetMs < 0.0f || causticTimeTargetMs > kMaxCausticTimeTargetMs)
        return outOfRange("causticTimeTargetMs", causticTimeTargetMs, 0.0f, kMaxCausticTimeTargetMs);
    if (!std::isfinite(causticReceiverReach) || causticReceiverReach < 0.0f || causticReceiverReach > kMaxCausticReceiverReach)
        return outOfRange("causticReceiverReach", causticReceiverReach, 0.0f, kMaxCausticReceiverReach);
    if (maxSpecularDepth < 1 || maxSpecularDepth > kMaxSpecularDepth)
        return outOfRange("maxSpecularDepth", maxSpecularDepth, 1u, kMaxSpecularDepth);
    if (maxStoredHits < 1 || maxStoredHits > kMaxStoredHits)
        return outOfRange("maxStoredHits", maxStoredHits, 1u, kMaxStoredHits);
    if (!std::isfinite(sphereRadiusScale) || sphereRadiusScale <= 0.0f || sphereRadiusScale > 64.0f)
        return outOfRange("sphereRadiusScale", sphereRadiusScale, 1e-6f, 64.0f);
    if (!std::isfinite(sphereWorldRadius) || sphereWorldRadius <= 0.0f || sphereWorldRadius > 1e3f)
        return outOfRange("sphereWorldRadius", sphereWorldRadius, 1e-6f, 1e3f);
    if (!std::isfinite(sphereMinMagnification) || sphereMinMagnification <= 0.0f || sphereMinMagnification > 1.0f)
        return outOfRange("sphereMinMagnification", sphereMinMagnification, 1e-6f, 1.0f);
    if (!std::isfinite(sphereMaxMagnification) || sphereMaxMagnification < 1.0f || sphereMaxMagnification > 1e3f)
        return outOfRange("sphereMaxMagnification", sphereMaxMagnification, 1.0f, 1e3f);
    if (!std::isfinite(sphereMinRadius) || sphereMinRadius <= 0.0f || sphereMinRadius > 1e3f)
        return outOfRange("sphereMinRadius", sphereMinRadius, 1e-6f, 1e3f);
    if (!std::isfinite(sphereMaxRadius) || sphereMaxRadius < sphereMinRadius || sphereMaxRadius > 1e3f)
        return outOfRange("sphereMaxRadius", sphereMaxRadius, sphereMinRadius, 1e3f);
    if (filterMaxHistory < 1 || filterMaxHistory > kMaxFilterHistory)
        return outOfRange("filterMaxHistory", filterMaxHistory, 1u, kMaxFilterHistory);
    if (filterPoolTiles > kMaxFilterPoolTiles) return outOfRange("filterPoolTiles", filterPoolTiles, 0u, kMaxFilterPoolTiles);
    if (atrousIterations > kMaxAtrousIterations)
        return outOfRange("atrousIterations", atrousIterations, 0u, kMaxAtrousIterations);
    if (!std::isfinite(filterLuminanceSigma) || filterLuminanceSigma <= 0.0f || filterLuminanceSigma > kMaxFilterLuminanceSigma)
        return outOfRange("filterLuminanceSigma", filterLuminanceSigma, 1e-6f, kMaxFilterLuminanceSigma);
    if (!std::isfinite(exposure) || exposure <= 0.0f) return makeError("CausticsSettings::exposure must be > 0");
    if (framesInFlight < 1 || framesInFlight > kMaxFramesInFlight)
        return outOfRange("framesInFlight", framesInFlight, 1u, kMaxFramesInFlight);
    return okStatus();
}

}  // namespace caustics
