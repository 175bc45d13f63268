// The last a-trous iteration: pool to caustics.radiance (atrous_body.hlsli).
#define kAtrousLast 1
#include "caustic_filter/atrous_body.hlsli"
