#ifndef CAUSTICS_COMMON_GATHER_DISK_H
#define CAUSTICS_COMMON_GATHER_DISK_H
// The second-type gather region (paper 3.3): a disk on the diffuse receiver, centred where the pixel's
// camera path lands, radius from the pixel's footprint there (common/ray_differential.h) and clamped;
// docs/caustics.md "Second-type footprint" and docs/physics.md "Second-type density estimate".
#include "common/lang.h"

CAUSTICS_SHARED_BEGIN

// Half-thickness of the disk relative to its radius: a hit counts when its distance to the tangent
// plane is below kGatherDiskThickness * r. A receiver of curvature radius Rc leaves the tangent plane
// by r^2 / (2 Rc) at the disk's rim, so curved receivers down to Rc = 2 r keep their whole disk.
CAUSTICS_CONST float kGatherDiskThickness = 0.25f;

// Wall probes: rays in the tangent plane at this many evenly spaced azimuths find the nearest
// occluder; the radius shrinks to cos(pi / kWallProbeCount) times that distance, which keeps the disk
// on this side of any planar wall whatever the wall's orientation.
CAUSTICS_CONST uint kWallProbeCount = 8u;
CAUSTICS_CONST float kWallProbeCosHalfStep = 0.923879532511287f;  // cos(pi / 8)

// Folds of the camera path: where the pixel-to-receiver map folds, dP/dx and dP/dy turn parallel and the
// footprint's area goes to zero while its length does not (a pixel there sees a thin strip of the
// receiver, second-order terms the differential leaves out). The footprint width never drops below this
// fraction of the footprint's major axis, so the disk keeps about the photons an ordinary pixel of that
// length gathers; footprints less elongated than 1 : 1 / kFoldMinorFraction^2 = 1 : 16 are untouched
// (docs/physics.md "Folds of the camera path": half the axis blurred the water glass's focal spike).
CAUSTICS_CONST float kFoldMinorFraction = 0.25f;

struct GatherRadiusLimits {
    float scale;             // CausticsSettings::sphereRadiusScale: radius in footprint widths
    float minMagnification;  // footprint width clamp relative to the unfolded pixel width
    float maxMagnification;
    float minRadius;         // metres
    float maxRadius;         // metres
};

// Radius of the gather disk for a pixel whose footprint parallelogram on the receiver has area
// `footprintArea` (m^2) and major axis `footprintMajorAxis` (m), and whose unfolded width (path length x
// pixel angle, the footprint without the specular chain's magnification) is `unfoldedWidth` (m). The
// width sqrt(area), at least kFoldMinorFraction x the major axis (folds), is clamped to
// [minMagnification, maxMagnification] x unfoldedWidth (ray differentials collapse where the camera
// path focuses and blow up at grazing incidence), scaled, then clamped to [minRadius, maxRadius].
CAUSTICS_FN float gatherDiskRadius(float footprintArea, float footprintMajorAxis, float unfoldedWidth, GatherRadiusLimits l) {
    float width = sqrt(max(footprintArea, 0.0f));
    float foldWidth = kFoldMinorFraction * footprintMajorAxis;
    if (foldWidth > width) width = foldWidth;      // false when either is NaN
    if (!(width == width)) width = unfoldedWidth;  // NaN from a degenerate differential
    width = clamp(width, l.minMagnification * unfoldedWidth, l.maxMagnification * unfoldedWidth);
    return clamp(l.scale * width, l.minRadius, l.maxRadius);
}

// True when the stored forward hit at p lies in the gather disk (centre c, unit receiver normal n on
// the side the camera path arrived from, radius r): inside the sphere of radius r and within the
// disk's thickness of the tangent plane. The sphere part is the expression the sphere TLAS's
// intersection shader evaluates; the plane part stops hits on other sheets of the same object.
CAUSTICS_FN bool insideGatherDisk(float3 p, float3 c, float3 n, float r) {
    float3 d = p - c;
    float h = dot(d, n);
    return dot(d, d) < r * r && abs(h) < kGatherDiskThickness * r;
}

CAUSTICS_SHARED_END

#endif  // CAUSTICS_COMMON_GATHER_DISK_H
