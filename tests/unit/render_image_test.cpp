// Image files: PFM is lossless, PNG is 8-bit sRGB, failed writes name the file.
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <gtest/gtest.h>
#include <stb/stb_image.h>

#include "picture/image.hpp"

namespace gem {
namespace {

std::filesystem::path scratch_dir(const std::string& name) {
    const std::filesystem::path dir =
        std::filesystem::path(GEM_ARTIFACT_DIR) / "render_image_test" / name;
    std::filesystem::create_directories(dir);
    return dir;
}

Image sample_image() {
    Image img(3, 2);
    img.at(0, 0) = {0.0f, 0.18f, 1.0f, 1.0f};
    img.at(1, 0) = {-2.5f, 1e-7f, 1234.5f, 1.0f};
    img.at(2, 0) = {0.5f, 0.25f, 0.125f, 1.0f};
    img.at(0, 1) = {3.0f, 2.0f, 1.0f, 1.0f};
    img.at(1, 1) = {1e30f, -0.0f, 7.75f, 1.0f};
    img.at(2, 1) = {0.1f, 0.2f, 0.3f, 1.0f};
    return img;
}

TEST(RenderImage, PfmRoundTripsExactly) {
    const Image img = sample_image();
    const auto path = scratch_dir("pfm") / "sample.pfm";
    ASSERT_TRUE(write_pfm(img, path).ok());
    Result<Image> back = read_pfm(path);
    ASSERT_TRUE(back.ok()) << back.error();
    ASSERT_EQ(back.value().width, 3);
    ASSERT_EQ(back.value().height, 2);
    for (int y = 0; y < 2; ++y) {
        for (int x = 0; x < 3; ++x) {
            for (int c = 0; c < 3; ++c) {
                EXPECT_EQ(back.value().at(x, y)[c], img.at(x, y)[c]) << x << "," << y;
            }
        }
    }
}

TEST(RenderImage, PfmLayoutIsHeaderThenBottomRowLittleEndian) {
    const auto path = scratch_dir("pfm") / "layout.pfm";
    ASSERT_TRUE(write_pfm(sample_image(), path).ok());
    std::ifstream in(path, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), {});
    const std::string header = "PF\n3 2\n-1.0\n";
    ASSERT_EQ(bytes.size(), header.size() + 3 * 2 * 3 * 4);
    EXPECT_EQ(bytes.substr(0, header.size()), header);
    // The first value stored is the red of the bottom-left pixel: 3.0f = 0x40400000.
    const unsigned char expected[4] = {0x00, 0x00, 0x40, 0x40};
    EXPECT_EQ(std::memcmp(bytes.data() + header.size(), expected, 4), 0);
}

TEST(RenderImage, PngIsSrgbEncodedEightBit) {
    Image img(2, 1);
    img.at(0, 0) = {0.0f, 0.18f, 1.0f, 1.0f};
    img.at(1, 0) = {2.0f, 0.0031308f, 0.5f, 1.0f};
    const auto path = scratch_dir("png") / "srgb.png";
    ASSERT_TRUE(write_png(img, path).ok());
    int w = 0, h = 0, n = 0;
    unsigned char* data = stbi_load(path.c_str(), &w, &h, &n, 3);
    ASSERT_NE(data, nullptr);
    ASSERT_EQ(w, 2);
    ASSERT_EQ(h, 1);
    EXPECT_EQ(n, 3);
    // By hand, sRGB(x) = 1.055 x^(1/2.4) - 0.055: 0.18 -> 0.46137 -> 117.65 -> 118;
    // 0.0031308 -> 12.92 x = 0.040450 -> 10.31 -> 10; 0.5 -> 0.73536 -> 187.52 -> 188;
    // values above 1 clip to 255.
    const int expected[6] = {0, 118, 255, 255, 10, 188};
    for (int i = 0; i < 6; ++i) EXPECT_EQ(data[i], expected[i]) << i;
    stbi_image_free(data);

    Result<Image> back = read_png(path);
    ASSERT_TRUE(back.ok()) << back.error();
    EXPECT_NEAR(back.value().at(0, 0).y, 0.18f, 0.003f);
    EXPECT_NEAR(back.value().at(1, 0).z, 0.5f, 0.003f);
    EXPECT_EQ(back.value().at(1, 0).w, 1.0f);
}

TEST(RenderImage, FailedWritesAndReadsNameTheFile) {
    const auto missing = scratch_dir("fail") / "no-such-folder" / "x.png";
    Result<std::filesystem::path> png = write_png(Image(2, 2), missing);
    ASSERT_FALSE(png.ok());
    EXPECT_NE(png.error().find("no-such-folder/x.png"), std::string::npos) << png.error();
    Result<std::filesystem::path> pfm = write_pfm(Image(2, 2), missing.parent_path() / "y.pfm");
    ASSERT_FALSE(pfm.ok());
    EXPECT_NE(pfm.error().find("y.pfm"), std::string::npos) << pfm.error();

    const auto bad = scratch_dir("fail") / "bad.pfm";
    std::ofstream(bad) << "PF\n1 1\n-1.0\nabc";  // the data ends early
    Result<Image> read = read_pfm(bad);
    ASSERT_FALSE(read.ok());
    EXPECT_NE(read.error().find("bad.pfm"), std::string::npos) << read.error();
    const auto text = scratch_dir("fail") / "text.png";
    std::ofstream(text) << "not a picture";
    Result<Image> png_read = read_png(text);
    ASSERT_FALSE(png_read.ok());
    EXPECT_NE(png_read.error().find("text.png"), std::string::npos) << png_read.error();
}

TEST(RenderImage, WriteReplacesAnExistingFileWhole) {
    const auto path = scratch_dir("replace") / "a.pfm";
    ASSERT_TRUE(write_pfm(Image(4, 4, glm::vec4(1.0f)), path).ok());
    ASSERT_TRUE(write_pfm(Image(1, 1, glm::vec4(2.0f)), path).ok());
    Result<Image> back = read_pfm(path);
    ASSERT_TRUE(back.ok());
    EXPECT_EQ(back.value().width, 1);
    EXPECT_EQ(back.value().at(0, 0).x, 2.0f);
    EXPECT_FALSE(std::filesystem::exists(path.string() + ".part"));
}

}  // namespace
}  // namespace gem
