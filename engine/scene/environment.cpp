#include "scene/environment.hpp"

#include <algorithm>
#include <cmath>

#include <stb/stb_image.h>

#include "picture/image.hpp"

namespace gem {

namespace {

constexpr double kPi = 3.14159265358979323846;

}  // namespace

Environment Environment::studio() {
    Environment env;
    env.kind_ = Kind::studio;
    return env;
}

Environment Environment::uniform(const glm::dvec3& colour) {
    Environment env;
    env.kind_ = Kind::uniform;
    env.colour_ = colour;
    return env;
}

Environment Environment::from_pixels(int width, int height, std::vector<glm::vec3> pixels) {
    assert(width > 0 && height > 0);
    assert(pixels.size() == static_cast<std::size_t>(width) * height);
    Environment env;
    env.kind_ = Kind::image;
    env.width_ = width;
    env.height_ = height;
    env.pixels_ = std::move(pixels);
    return env;
}

Result<Environment> Environment::load_image(const std::filesystem::path& path) {
    int w = 0;
    int h = 0;
    int channels = 0;
    std::vector<glm::vec3> pixels;
    if (stbi_is_hdr(path.c_str()) != 0) {
        float* data = stbi_loadf(path.c_str(), &w, &h, &channels, 3);
        if (data == nullptr) {
            return Error{"environment " + path.string() + ": " + stbi_failure_reason()};
        }
        pixels.resize(static_cast<std::size_t>(w) * h);
        for (std::size_t i = 0; i < pixels.size(); ++i) {
            pixels[i] = glm::vec3(data[3 * i], data[3 * i + 1], data[3 * i + 2]);
        }
        stbi_image_free(data);
    } else {
        // 8-bit images are sRGB-encoded; decode ourselves rather than stb's plain 2.2 gamma.
        Result<Image> image = read_png(path);
        if (!image) return Error{"environment " + image.error()};
        w = image.value().width;
        h = image.value().height;
        pixels.resize(image.value().pixels.size());
        for (std::size_t i = 0; i < pixels.size(); ++i) {
            pixels[i] = glm::vec3(image.value().pixels[i]);
        }
    }
    if (w < 2 || h < 2) {
        return Error{"environment " + path.string() + ": the image is smaller than 2×2"};
    }
    return from_pixels(w, h, std::move(pixels));
}

glm::dvec3 Environment::radiance(const glm::dvec3& d) const {
    switch (kind_) {
        case Kind::uniform:
            return colour_ * intensity_;
        case Kind::image:
            return image_radiance(d) * intensity_;
        case Kind::studio:
            break;
    }
    return studio_radiance(d) * intensity_;
}

glm::dvec3 Environment::mean_radiance() const {
    // Points of a Fibonacci lattice: equal areas of the sphere, z evenly spaced in (-1, 1),
    // turned by the golden angle each.
    constexpr int kDirections = 4096;
    const double golden_angle = 3.14159265358979323846 * (3.0 - std::sqrt(5.0));
    glm::dvec3 sum(0.0);
    for (int i = 0; i < kDirections; ++i) {
        const double z = 1.0 - (2.0 * i + 1.0) / kDirections;
        const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
        const double phi = golden_angle * i;
        sum += radiance({r * std::cos(phi), z, r * std::sin(phi)});
    }
    return sum / double(kDirections);
}

Environment Environment::with_intensity(double intensity) const {
    Environment scaled = *this;
    scaled.intensity_ = intensity_ * intensity;
    return scaled;
}

glm::dvec3 Environment::image_radiance(const glm::dvec3& d) const {
    // Longitude 0 (the centre column) looks toward -z; latitude from +y (top row) to -y.
    const double u = std::atan2(d.x, -d.z) / (2.0 * kPi) + 0.5;
    const double v = std::acos(std::clamp(d.y, -1.0, 1.0)) / kPi;
    // Texel centres sit at half-integer positions; columns wrap around, rows clamp.
    const double fx = u * width_ - 0.5;
    const double fy = std::clamp(v * height_ - 0.5, 0.0, height_ - 1.0);
    const double x0f = std::floor(fx);
    const double y0f = std::floor(fy);
    const double tx = fx - x0f;
    const double ty = fy - y0f;
    const int x0 = ((static_cast<int>(x0f) % width_) + width_) % width_;
    const int x1 = (x0 + 1) % width_;
    const int y0 = static_cast<int>(y0f);
    const int y1 = std::min(y0 + 1, height_ - 1);
    auto texel = [&](int x, int y) {
        return glm::dvec3(pixels_[static_cast<std::size_t>(y) * width_ + x]);
    };
    const glm::dvec3 top = glm::mix(texel(x0, y0), texel(x1, y0), tx);
    const glm::dvec3 bottom = glm::mix(texel(x0, y1), texel(x1, y1), tx);
    return glm::mix(top, bottom, ty);
}

}  // namespace gem
