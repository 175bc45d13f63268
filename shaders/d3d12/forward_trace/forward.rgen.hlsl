// Forward trace, float radiance (compare-exchange on float bits; see radiance_atomics.hlsli).
#include "forward_trace/forward_body.hlsli"
