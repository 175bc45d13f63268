// Gather any-hit, float radiance (compare-exchange on float bits).
#include "backward_trace/gather_body.hlsli"
