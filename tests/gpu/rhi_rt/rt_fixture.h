#pragma once
// Fixture of the ray-tracing GPU tests: the shared GpuTest device (lavapipe, validation on, any
// warning or error fails the test) plus `dev()` for the helpers that take an IDevice&.
#include "gpu_test.h"
#include "rt_test_support.h"

namespace caustics::test {

class RayTracingTest : public GpuTest {
protected:
    rhi::IDevice& dev() { return *device; }
};

}  // namespace caustics::test
