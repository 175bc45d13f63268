#include "caustics/scene/procedural_textures.h"

#include <algorithm>
#include <cmath>

namespace caustics::scene {

namespace {

// Integer hash (a "lowbias32" style avalanche mix) -> [0,1): deterministic, no RNG state.
float hash01(uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    x ^= x >> 16;
    return float(x >> 8) / 16777216.0f;
}

float valueNoise(float x, float y, uint32_t period, uint32_t seed) {
    int xi = int(std::floor(x)), yi = int(std::floor(y));
    float fx = x - float(xi), fy = y - float(yi);
    auto corner = [&](int cx, int cy) {
        uint32_t px = uint32_t(cx) % period, py = uint32_t(cy) % period;   // tileable
        return hash01(px * 73856093u ^ py * 19349663u ^ seed * 83492791u);
    };
    float sx = fx * fx * (3.0f - 2.0f * fx), sy = fy * fy * (3.0f - 2.0f * fy);
    float a = corner(xi, yi), b = corner(xi + 1, yi), c = corner(xi, yi + 1), d = corner(xi + 1, yi + 1);
    return (a * (1 - sx) + b * sx) * (1 - sy) + (c * (1 - sx) + d * sx) * sy;
}

// Linear [0,1] -> sRGB-encoded byte (IEC 61966-2-1 transfer function).
uint8_t toSrgb8(float linear) {
    float c = std::clamp(linear, 0.0f, 1.0f);
    float s = c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
    return uint8_t(std::lround(s * 255.0f));
}

Texture makeTexture(const std::string& name, uint32_t size) {
    Texture t;
    t.name = name;
    t.width = t.height = size;
    t.rgba8.resize(size_t(size) * size * 4);
    return t;
}

void put(Texture& t, uint32_t x, uint32_t y, const glm::vec3& linear) {
    uint8_t* p = &t.rgba8[(size_t(y) * t.width + x) * 4];
    p[0] = toSrgb8(linear.r);
    p[1] = toSrgb8(linear.g);
    p[2] = toSrgb8(linear.b);
    p[3] = 255;
}

}  // namespace

Texture makeTileTexture(uint32_t size, const glm::vec3& tile, const glm::vec3& grout, uint32_t tiles, float jitter,
                        uint32_t seed) {
    Texture t = makeTexture("tiles", size);
    uint32_t cell = std::max(1u, size / std::max(1u, tiles));
    uint32_t groutWidth = std::max(1u, cell / 16);
    for (uint32_t y = 0; y < size; ++y)
        for (uint32_t x = 0; x < size; ++x) {
            uint32_t cx = x / cell, cy = y / cell;
            bool isGrout = (x % cell) < groutWidth || (y % cell) < groutWidth;
            float n = valueNoise(float(x) / 8.0f, float(y) / 8.0f, std::max(1u, size / 8), seed);
            float k = 1.0f + jitter * (hash01(cx * 911u + cy * 3571u + seed) - 0.5f) * 2.0f + 0.08f * (n - 0.5f);
            put(t, x, y, isGrout ? grout : tile * k);
        }
    return t;
}

Texture makeNoiseTexture(uint32_t size, const glm::vec3& color, float amplitude, uint32_t seed) {
    Texture t = makeTexture("noise", size);
    for (uint32_t y = 0; y < size; ++y)
        for (uint32_t x = 0; x < size; ++x) {
            float n = 0.0f, w = 0.5f;
            for (uint32_t octave = 0; octave < 4; ++octave, w *= 0.5f) {
                float f = float(4u << octave) / float(size);
                n += w * valueNoise(float(x) * f, float(y) * f, 4u << octave, seed + octave);
            }
            put(t, x, y, color * (1.0f + amplitude * (2.0f * n - 0.9375f)));
        }
    return t;
}

Texture makeWoodTexture(uint32_t size, const glm::vec3& light, const glm::vec3& dark, uint32_t seed) {
    Texture t = makeTexture("wood", size);
    for (uint32_t y = 0; y < size; ++y)
        for (uint32_t x = 0; x < size; ++x) {
            float n = valueNoise(float(x) / 16.0f, float(y) / 4.0f, std::max(1u, size / 4), seed);
            float rings = 0.5f + 0.5f * std::sin(float(y) / float(size) * 6.2831853f * 12.0f + 4.0f * n);
            put(t, x, y, glm::mix(light, dark, 0.35f * rings + 0.1f * n));
        }
    return t;
}

Texture makeSolidTexture(const glm::vec3& color, const std::string& name) {
    Texture t = makeTexture(name, 1);
    put(t, 0, 0, color);
    return t;
}

}  // namespace caustics::scene
