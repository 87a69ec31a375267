// The present pass on llvmpipe (EGL surfaceless): a picture with a known colour at every pixel
// is drawn into a plain 8-bit RGBA framebuffer standing in for the GBM window surface (which
// is XRGB8888, not sRGB), at each quarter turn. Where each pixel must land is computed
// independently of the shader's matrix, by turning pixel indices as a sheet of paper turns;
// the bytes must come back as stored: exactly where the pass copies them undecoded, within a
// code where the sampler decodes sRGB and the shader encodes it. Each test runs both copies.

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <optional>
#include <vector>

#include <GLES3/gl3.h>

#include "display/present_pass.hpp"
#include "gpu/egl_context.hpp"
#include "gpu/gl_handles.hpp"
#include "gpu/render_target.hpp"

namespace gem::kiosk {
namespace {

struct Rgb {
    int r, g, b;
};

// A plain RGBA8 colour buffer (no sRGB encoding on write), like the window surface.
struct WindowStandIn {
    gpu::Texture colour;
    gpu::Framebuffer framebuffer;
    int width, height;

    WindowStandIn(int w, int h)
        : colour(gpu::make_texture()), framebuffer(gpu::make_framebuffer()), width(w), height(h) {
        glBindTexture(GL_TEXTURE_2D, colour.get());
        glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA8, w, h);
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.get());
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, colour.get(),
                               0);
    }
    // Pixel (x, y) with y counted down from the top.
    std::vector<std::uint8_t> read() const {
        std::vector<std::uint8_t> bytes(static_cast<std::size_t>(width) * height * 4);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer.get());
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, bytes.data());
        return bytes;
    }
    const std::uint8_t* at(const std::vector<std::uint8_t>& bytes, int x, int y) const {
        return bytes.data() + (static_cast<std::size_t>(height - 1 - y) * width + x) * 4;
    }
};

// Stores sRGB bytes into the picture; `colour(x, y)` with y counted down from the top.
template <class Colour>
void fill_picture(const gpu::RenderTarget& picture, Colour colour) {
    const int w = picture.width();
    const int h = picture.height();
    std::vector<std::uint8_t> bytes(static_cast<std::size_t>(w) * h * 4);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const Rgb c = colour(x, y);
            std::uint8_t* p = bytes.data() + (static_cast<std::size_t>(h - 1 - y) * w + x) * 4;
            p[0] = static_cast<std::uint8_t>(c.r);
            p[1] = static_cast<std::uint8_t>(c.g);
            p[2] = static_cast<std::uint8_t>(c.b);
            p[3] = 255;
        }
    }
    glBindTexture(GL_TEXTURE_2D, picture.colour_texture());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, bytes.data());
}

class PresentPassCopy : public ::testing::TestWithParam<PresentPass::Copy> {
  protected:
    void SetUp() override {
        auto made = gpu::EglContext::headless();
        ASSERT_TRUE(made) << made.error();
        context.emplace(std::move(made).value());
        if (GetParam() == PresentPass::Copy::bytes &&
            PresentPass::supported_copy() != PresentPass::Copy::bytes) {
            GTEST_SKIP() << "this GL cannot skip the sRGB decode";
        }
        auto made_pass = PresentPass::make(GetParam());
        ASSERT_TRUE(made_pass) << made_pass.error();
        pass.emplace(std::move(made_pass).value());
    }
    // A copied byte must come back as it was; a decoded and encoded one may round by a code.
    int tolerance() const { return GetParam() == PresentPass::Copy::bytes ? 0 : 1; }

    std::optional<gpu::EglContext> context;
    std::optional<PresentPass> pass;
};

TEST_P(PresentPassCopy, EveryPixelLandsWhereTheTurnSendsItWithItsBytes) {
    const int w = 5;  // a picture that is not square, so a wrong turn cannot pass
    const int h = 3;
    auto picture = gpu::RenderTarget::make(w, h);
    ASSERT_TRUE(picture) << picture.error();
    // Distinct colours at every pixel, spread over the sRGB curve (dark values are where the
    // linear and power segments meet).
    auto colour = [](int x, int y) {
        return Rgb{7 + 50 * x, 3 + 120 * y, (x * 31 + y * 97 + 200) % 256};
    };
    fill_picture(picture.value(), colour);

    for (int rotation : {0, 90, 180, 270}) {
        const bool quarter = rotation % 180 != 0;
        WindowStandIn window(quarter ? h : w, quarter ? w : h);
        ASSERT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
        auto drawn = pass->draw(picture.value(), rotation, {window.width, window.height});
        ASSERT_TRUE(drawn) << drawn.error();
        const auto bytes = window.read();
        for (int y = 0; y < h; ++y) {
            for (int x = 0; x < w; ++x) {
                // Clockwise quarter turn of a w x h sheet: (x, y) -> (h - 1 - y, x).
                int sx = x;
                int sy = y;
                if (rotation == 90) {
                    sx = h - 1 - y;
                    sy = x;
                } else if (rotation == 180) {
                    sx = w - 1 - x;
                    sy = h - 1 - y;
                } else if (rotation == 270) {
                    sx = y;
                    sy = w - 1 - x;
                }
                const std::uint8_t* p = window.at(bytes, sx, sy);
                const Rgb expected = colour(x, y);
                const int t = tolerance();
                EXPECT_LE(std::abs(p[0] - expected.r), t) << rotation << " " << x << "," << y;
                EXPECT_LE(std::abs(p[1] - expected.g), t) << rotation << " " << x << "," << y;
                EXPECT_LE(std::abs(p[2] - expected.b), t) << rotation << " " << x << "," << y;
                EXPECT_EQ(p[3], 255);
            }
        }
    }
}

TEST_P(PresentPassCopy, EveryByteValueRoundTrips) {
    auto picture = gpu::RenderTarget::make(256, 1);
    ASSERT_TRUE(picture) << picture.error();
    fill_picture(picture.value(), [](int x, int) { return Rgb{x, 255 - x, (x * 7) % 256}; });
    WindowStandIn window(256, 1);
    ASSERT_TRUE(pass->draw(picture.value(), 0, {256, 1}));
    const auto bytes = window.read();
    int worst = 0;
    for (int x = 0; x < 256; ++x) {
        const std::uint8_t* p = window.at(bytes, x, 0);
        worst = std::max({worst, std::abs(p[0] - x), std::abs(p[1] - (255 - x)),
                          std::abs(p[2] - (x * 7) % 256)});
    }
    EXPECT_LE(worst, tolerance());
    RecordProperty("worst_byte_error", worst);
    // The undecoding sampler is not left on the unit: a cross-fade after the pass samples
    // the picture as linear light.
    GLint sampler = -1;
    glActiveTexture(GL_TEXTURE0);
    glGetIntegerv(GL_SAMPLER_BINDING, &sampler);
    EXPECT_EQ(sampler, 0);
}

// A region given: the pixels of its tiles show the new picture, the others keep what the window
// held (a back buffer that lacks only those tiles).
TEST_P(PresentPassCopy, ARegionDrawsOnlyItsOwnTiles) {
    // Tiles of 32: three columns (the last 16 wide) and two rows (the last 8 high).
    const int w = 80, h = 40;
    auto picture = gpu::RenderTarget::make(w, h);
    ASSERT_TRUE(picture) << picture.error();
    WindowStandIn window(w, h);
    fill_picture(picture.value(), [](int, int) { return Rgb{10, 20, 30}; });
    ASSERT_TRUE(pass->draw(picture.value(), 0, {w, h}));
    fill_picture(picture.value(), [](int, int) { return Rgb{200, 100, 50}; });
    gpu::TileSet region(w, h);
    region.mark({40, 5, 41, 6});    // tile (1, 0), y up
    region.mark({70, 39, 71, 40});  // tile (2, 1), the partial corner
    ASSERT_TRUE(pass->draw(picture.value(), 0, {w, h}, &region));
    const auto bytes = window.read();
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const int y_up = h - 1 - y;
            const bool inside = (x >= 32 && x < 64 && y_up < 32) || (x >= 64 && y_up >= 32);
            EXPECT_NEAR(window.at(bytes, x, y)[0], inside ? 200 : 10, tolerance())
                << x << ", " << y;
        }
    }
    GLboolean scissor = GL_TRUE;
    glGetBooleanv(GL_SCISSOR_TEST, &scissor);
    EXPECT_EQ(scissor, GL_FALSE) << "the pass leaves the scissor test off";
}

INSTANTIATE_TEST_SUITE_P(Copies, PresentPassCopy,
                         ::testing::Values(PresentPass::Copy::bytes, PresentPass::Copy::reencode),
                         [](const auto& param_info) {
                             return param_info.param == PresentPass::Copy::bytes ? "Bytes"
                                                                                 : "Reencode";
                         });

}  // namespace
}  // namespace gem::kiosk
