#pragma once
// Float RGBA images in linear light, and their files: 8-bit sRGB PNG for people, the lossless
// "PF" portable float map for exact comparisons. Writes are atomic (a temporary file renamed
// into place), so a failed write never leaves half a file where a good one was.

#include <cstdint>
#include <filesystem>
#include <vector>

#include <glm/glm.hpp>

#include "util/result.hpp"

namespace gem {

struct Image {
    int width = 0;
    int height = 0;
    std::vector<glm::vec4> pixels;  // row-major, top row first; linear RGB + alpha

    Image() = default;
    Image(int w, int h, glm::vec4 fill = glm::vec4(0.0f))
        : width(w), height(h), pixels(static_cast<std::size_t>(w) * h, fill) {}

    glm::vec4& at(int x, int y) { return pixels[static_cast<std::size_t>(y) * width + x]; }
    const glm::vec4& at(int x, int y) const {
        return pixels[static_cast<std::size_t>(y) * width + x];
    }
};

// 8 bits per channel, sRGB-encoded colour and linear alpha; `channels` is 3 (RGB) or 4 (RGBA).
std::vector<std::uint8_t> to_srgb8(const Image& image, int channels);

// Returns the path written; errors name the file and say why.
Result<std::filesystem::path> write_png(const Image& image, const std::filesystem::path& path,
                                        bool with_alpha = false);
Result<std::filesystem::path> write_pfm(const Image& image, const std::filesystem::path& path);

// PNG of any bit depth: colour decoded from sRGB to linear, alpha kept linear (1 if absent).
Result<Image> read_png(const std::filesystem::path& path);
// Colour PFM ("PF"), either byte order; alpha is 1.
Result<Image> read_pfm(const std::filesystem::path& path);

}  // namespace gem
