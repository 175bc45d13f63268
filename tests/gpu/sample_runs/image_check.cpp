// image-check: the assertions the sample's end-to-end tests make on the images it wrote (CTest runs
// the sample, then this). Values are 8-bit channels scaled to 0..1; alpha is ignored. Exit 0 = pass.
//   image-check mean FILE MIN [x y w h]           mean RGB over the region is at least MIN
//   image-check differ A B MIN [x y w h]          mean |A - B| over the region is at least MIN
//   image-check match A GOLDEN MAX [x y w h]      mean |A - GOLDEN| over the region is at most MAX
//   image-check brighter A B MIN [x y w h]        mean(B) - mean(A) over the region is at least MIN
//   image-check size FILE W H                     the image is W x H pixels
//   image-check shift A B DX DY MAXERR [x y w h]  the brightness-weighted centroid moves from A to B by
//                                                 (DX, DY) pixels, to within MAXERR pixels
//   image-check finite FILE                       every value is finite
// Every mode first requires every image it reads to be finite (no NaN or inf anywhere): a check on a
// mean or a centroid must not pass over, or be poisoned by, non-finite pixels.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "image_file.h"

using caustics::sample::FloatImage;

namespace {

struct Region {
    uint32_t x = 0, y = 0, w = 0, h = 0;
};

bool regionFrom(char** argv, int argc, int first, const FloatImage& image, Region& r) {
    r = {0, 0, image.width, image.height};
    if (argc == first) return true;
    if (argc != first + 4) return false;
    r = {uint32_t(std::atoi(argv[first])), uint32_t(std::atoi(argv[first + 1])), uint32_t(std::atoi(argv[first + 2])),
         uint32_t(std::atoi(argv[first + 3]))};
    return r.w > 0 && r.h > 0 && r.x + r.w <= image.width && r.y + r.h <= image.height;
}

double meanOver(const FloatImage& a, const FloatImage* b, const Region& r) {
    double sum = 0.0;
    for (uint32_t y = r.y; y < r.y + r.h; ++y)
        for (uint32_t x = r.x; x < r.x + r.w; ++x)
            for (uint32_t c = 0; c < 3; ++c) {
                size_t i = (size_t(y) * a.width + x) * a.channels + c;
                sum += b ? std::fabs(a.pixels[i] - b->pixels[i]) : a.pixels[i];
            }
    return sum / (3.0 * r.w * r.h);
}

// Centroid of the mean RGB over the region, pixel centres at +0.5; false when the region is black.
bool centroid(const FloatImage& image, const Region& r, double& cx, double& cy) {
    double sum = 0.0, sx = 0.0, sy = 0.0;
    for (uint32_t y = r.y; y < r.y + r.h; ++y)
        for (uint32_t x = r.x; x < r.x + r.w; ++x) {
            size_t i = (size_t(y) * image.width + x) * image.channels;
            double weight = (double(image.pixels[i]) + image.pixels[i + 1] + image.pixels[i + 2]) / 3.0;
            sum += weight;
            sx += weight * (x + 0.5);
            sy += weight * (y + 0.5);
        }
    if (!(sum > 0.0)) return false;
    cx = sx / sum;
    cy = sy / sum;
    return true;
}

int fail(const std::string& message) {
    std::fprintf(stderr, "image-check: %s\n", message.c_str());
    return 1;
}

// The image, or an error naming how many values are NaN or inf.
caustics::Result<FloatImage> readFinite(const char* path) {
    auto image = caustics::sample::readImage(path);
    if (!image) return image;
    size_t bad = 0;
    for (float v : image->pixels) bad += std::isfinite(v) ? 0 : 1;
    if (bad > 0)
        return caustics::makeError(std::string(path) + ": " + std::to_string(bad) + " of " + std::to_string(image->pixels.size()) +
                                   " values are not finite (NaN or inf)");
    return image;
}

// B's brightness-weighted centroid = A's + (DX, DY), to within MAXERR pixels.
int checkShift(int argc, char** argv) {
    if (argc != 7 && argc != 11) return fail("usage: image-check shift A B DX DY MAXERR [x y w h]");
    auto a = readFinite(argv[2]);
    auto b = readFinite(argv[3]);
    if (!a || !b) return fail(!a ? a.message() : b.message());
    if (a->width != b->width || a->height != b->height || a->channels < 3 || b->channels != a->channels)
        return fail("the images differ in size or channels");
    Region r;
    if (!regionFrom(argv, argc, 7, *a, r)) return fail("bad region");
    double ax, ay, bx, by;
    if (!centroid(*a, r, ax, ay) || !centroid(*b, r, bx, by)) return fail("an image is black over the region");
    double ex = ax + std::atof(argv[4]), ey = ay + std::atof(argv[5]), maxError = std::atof(argv[6]);
    double error = std::hypot(bx - ex, by - ey);
    std::printf("image-check: centroid (%.2f, %.2f) -> (%.2f, %.2f), expected (%.2f, %.2f): error %.2f px (need <= %.2f)\n",
                ax, ay, bx, by, ex, ey, error, maxError);
    return error <= maxError ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 3) return fail("usage: image-check mean FILE MIN | differ|match|brighter A B THRESHOLD [x y w h]");
    std::string mode = argv[1];
    if (mode == "finite" && argc == 3) {
        auto image = readFinite(argv[2]);
        if (!image) return fail(image.message());
        std::printf("image-check: every value of %s is finite\n", argv[2]);
        return 0;
    }
    if (argc < 4) return fail("usage: image-check mean FILE MIN | finite FILE | differ|match|brighter A B THRESHOLD [x y w h]");
    auto a = readFinite(argv[2]);
    if (!a) return fail(a.message());
    if (mode == "size" && argc == 5) {
        uint32_t w = uint32_t(std::atoi(argv[3])), h = uint32_t(std::atoi(argv[4]));
        std::printf("image-check: %s is %ux%u (need %ux%u)\n", argv[2], a->width, a->height, w, h);
        return a->width == w && a->height == h ? 0 : 1;
    }
    if (mode == "mean") {
        Region r;
        if (!regionFrom(argv, argc, 4, *a, r)) return fail("bad region");
        double mean = meanOver(*a, nullptr, r), min = std::atof(argv[3]);
        std::printf("image-check: mean %.4f (need >= %.4f) over %ux%u at %u,%u of %s\n", mean, min, r.w, r.h, r.x, r.y, argv[2]);
        return mean >= min ? 0 : 1;
    }
    if (argc < 5) return fail("differ/match need two files and a threshold");
    if (mode == "shift") return checkShift(argc, argv);
    auto b = readFinite(argv[3]);
    if (!b) return fail(b.message());
    if (a->width != b->width || a->height != b->height || a->channels < 3 || b->channels != a->channels)
        return fail("the images differ in size or channels");
    Region r;
    if (!regionFrom(argv, argc, 5, *a, r)) return fail("bad region");
    double threshold = std::atof(argv[4]);
    if (mode == "brighter") {
        double gain = meanOver(*b, nullptr, r) - meanOver(*a, nullptr, r);
        std::printf("image-check: mean(B) - mean(A) = %.4f (need >= %.4f)\n", gain, threshold);
        return gain >= threshold ? 0 : 1;
    }
    double diff = meanOver(*a, &*b, r);
    bool pass = mode == "differ" ? diff >= threshold : diff <= threshold;
    std::printf("image-check: mean |difference| %.4f (need %s %.4f) over %ux%u at %u,%u\n", diff,
                mode == "differ" ? ">=" : "<=", threshold, r.w, r.h, r.x, r.y);
    return pass ? 0 : 1;
}
