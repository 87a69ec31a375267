#include "picture/image.hpp"

#include <algorithm>
#include <cmath>

#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

#include "optics/colour.hpp"
#include "util/atomic_file.hpp"

namespace gem {

namespace {

std::uint8_t alpha_byte(double value01) {
    return static_cast<std::uint8_t>(std::lround(std::clamp(value01, 0.0, 1.0) * 255.0));
}

void append_bytes(void* context, void* data, int size) {
    auto* out = static_cast<std::vector<std::uint8_t>*>(context);
    const auto* bytes = static_cast<const std::uint8_t*>(data);
    out->insert(out->end(), bytes, bytes + size);
}

}  // namespace

std::vector<std::uint8_t> to_srgb8(const Image& image, int channels) {
    assert(channels == 3 || channels == 4);
    std::vector<std::uint8_t> bytes;
    bytes.reserve(image.pixels.size() * static_cast<std::size_t>(channels));
    for (const glm::vec4& p : image.pixels) {
        for (int c = 0; c < 3; ++c) bytes.push_back(linear_to_srgb8(p[c]));
        if (channels == 4) bytes.push_back(alpha_byte(p.w));
    }
    return bytes;
}

Result<std::filesystem::path> write_png(const Image& image, const std::filesystem::path& path,
                                        bool with_alpha) {
    assert(image.width > 0 && image.height > 0);
    const int channels = with_alpha ? 4 : 3;
    const std::vector<std::uint8_t> pixels = to_srgb8(image, channels);
    // Encoded to memory first so the file itself is written (and checked) by one routine.
    std::vector<std::uint8_t> png;
    const int encoded = stbi_write_png_to_func(append_bytes, &png, image.width, image.height,
                                               channels, pixels.data(), image.width * channels);
    if (encoded == 0 || png.empty()) {
        return Error{"cannot write " + path.string() + ": PNG encoding failed"};
    }
    return write_file_atomic(path, png.data(), png.size());
}

Result<Image> read_png(const std::filesystem::path& path) {
    int width = 0;
    int height = 0;
    int channels_in_file = 0;
    stbi_uc* data = stbi_load(path.c_str(), &width, &height, &channels_in_file, 4);
    if (data == nullptr) {
        return Error{"cannot read " + path.string() + ": " + stbi_failure_reason()};
    }
    Image image(width, height);
    for (std::size_t i = 0; i < image.pixels.size(); ++i) {
        const stbi_uc* p = data + 4 * i;
        image.pixels[i] = glm::vec4(srgb8_to_linear(p[0]), srgb8_to_linear(p[1]),
                                    srgb8_to_linear(p[2]), p[3] / 255.0);
    }
    stbi_image_free(data);
    return image;
}

}  // namespace gem
