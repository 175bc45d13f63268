// An a-trous iteration before the last: pool to pool (atrous_body.hlsli).
#include "caustic_filter/atrous_body.hlsli"
