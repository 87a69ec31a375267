// The portable float map: "PF" (colour), width and height, then a scale whose sign gives the
// byte order (negative = little-endian), then float32 RGB rows from the bottom row up
// (Paul Debevec's PFM description, https://www.pauldebevec.com/Research/HDR/PFM/).
#include <bit>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>

#include "picture/image.hpp"
#include "util/atomic_file.hpp"

namespace gem {

namespace {

std::uint32_t byte_swap(std::uint32_t v) {
    return (v >> 24) | ((v >> 8) & 0xff00u) | ((v << 8) & 0xff0000u) | (v << 24);
}

// Converts between the host's float layout and the file's byte order.
float from_file_order(std::uint32_t bits, bool file_little_endian) {
    if (file_little_endian != (std::endian::native == std::endian::little)) bits = byte_swap(bits);
    return std::bit_cast<float>(bits);
}

}  // namespace

Result<std::filesystem::path> write_pfm(const Image& image, const std::filesystem::path& path) {
    const std::string header =
        "PF\n" + std::to_string(image.width) + " " + std::to_string(image.height) + "\n-1.0\n";
    std::string bytes = header;
    bytes.reserve(header.size() + image.pixels.size() * 12);
    for (int y = image.height - 1; y >= 0; --y) {
        for (int x = 0; x < image.width; ++x) {
            for (int c = 0; c < 3; ++c) {
                std::uint32_t bits = std::bit_cast<std::uint32_t>(image.at(x, y)[c]);
                if (std::endian::native != std::endian::little) bits = byte_swap(bits);
                char out[4];
                std::memcpy(out, &bits, 4);
                bytes.append(out, 4);
            }
        }
    }
    return write_file_atomic(path, bytes.data(), bytes.size());
}

Result<Image> read_pfm(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return Error{"cannot read " + path.string() + ": cannot open the file"};
    std::string magic;
    long long width = 0;
    long long height = 0;
    double scale = 0.0;
    in >> magic >> width >> height >> scale;
    if (!in || magic != "PF") {
        return Error{path.string() + ": not a colour PFM (expected \"PF\", size and scale)"};
    }
    if (width <= 0 || height <= 0 || width > 65536 || height > 65536 || scale == 0.0) {
        return Error{path.string() + ": PFM header has a bad size or scale"};
    }
    in.get();  // the single whitespace byte that ends the header
    // Check that the pixels are there before allocating for them: a damaged header must not
    // ask for gigabytes.
    const auto header_end = static_cast<long long>(in.tellg());
    std::error_code ec;
    const auto file_bytes = static_cast<long long>(std::filesystem::file_size(path, ec));
    if (ec || header_end < 0 || file_bytes - header_end < 12 * width * height) {
        return Error{path.string() + ": PFM data ends early"};
    }
    const bool little_endian = scale < 0.0;
    Image image(static_cast<int>(width), static_cast<int>(height), glm::vec4(1.0f));
    for (int y = image.height - 1; y >= 0; --y) {
        for (int x = 0; x < image.width; ++x) {
            for (int c = 0; c < 3; ++c) {
                std::uint32_t bits = 0;
                if (!in.read(reinterpret_cast<char*>(&bits), 4)) {
                    return Error{path.string() + ": PFM data ends early"};
                }
                image.at(x, y)[c] = from_file_order(bits, little_endian);
            }
        }
    }
    return image;
}

}  // namespace gem
