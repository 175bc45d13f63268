// The headless sample's last guard against non-finite radiance (samples/sponza/finite_output.h): NaN and
// inf pixels are written as 0, every other pixel unchanged, with a warning naming the file and the count.
#include <cmath>
#include <filesystem>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "finite_output.h"
#include "image_file.h"

namespace caustics::sample {
namespace {

TEST(FiniteOutput, NonFinitePixelsAreWrittenAsZeroAndCounted) {
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    const uint32_t w = 4, h = 2;
    std::vector<float> hdr(size_t(w) * h * 4, 0.5f);
    hdr[0] = nan;           // pixel 0: red NaN
    hdr[4 * 3 + 1] = inf;   // pixel 3: green +inf
    hdr[4 * 6 + 3] = -inf;  // pixel 6: alpha -inf
    EXPECT_EQ(countNonFinitePixels(hdr), 3u);
    auto path = (std::filesystem::temp_directory_path() / "caustics_finite_output.exr").string();
    testing::internal::CaptureStderr();
    ASSERT_TRUE(writeFiniteRenderedImage(path, w, h, std::vector<uint8_t>(size_t(w) * h * 4, 128), hdr).ok());
    std::string warning = testing::internal::GetCapturedStderr();
    EXPECT_NE(warning.find(path + ": 3 of 8 pixels have non-finite radiance (NaN or inf), written as 0"), std::string::npos)
        << warning;
    auto image = readImage(path);
    ASSERT_TRUE(image.ok()) << image.message();
    ASSERT_EQ(image->pixels.size(), hdr.size());
    for (size_t i = 0; i < hdr.size(); ++i) EXPECT_EQ(image->pixels[i], std::isfinite(hdr[i]) ? hdr[i] : 0.0f) << "value " << i;
}

TEST(FiniteOutput, AFiniteImageIsWrittenWithoutAWarning) {
    std::vector<float> hdr(4 * 4, 0.25f);
    auto path = (std::filesystem::temp_directory_path() / "caustics_finite_output_ok.exr").string();
    testing::internal::CaptureStderr();
    ASSERT_TRUE(writeFiniteRenderedImage(path, 2, 2, std::vector<uint8_t>(16, 64), hdr).ok());
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
}

}  // namespace
}  // namespace caustics::sample
