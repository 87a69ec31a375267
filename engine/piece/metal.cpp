#include "piece/metal.hpp"

#include <array>
#include <utility>

namespace gem {

namespace {

constexpr std::array<std::pair<Metal, const char*>, 4> kNames{{
    {Metal::yellow_gold, "yellow_gold"},
    {Metal::white_gold, "white_gold"},
    {Metal::platinum, "platinum"},
    {Metal::silver, "silver"},
}};

}  // namespace

std::optional<Metal> parse_metal(std::string_view name) {
    for (const auto& [metal, text] : kNames) {
        if (name == text) return metal;
    }
    return std::nullopt;
}

const char* to_string(Metal metal) {
    for (const auto& [m, text] : kNames) {
        if (m == metal) return text;
    }
    return "?";
}

glm::vec3 metal_f0(Metal metal) {
    // Measured sRGB colours from Filament's material guide ("Physically Based Rendering in
    // Filament", Guy & Agopian, table "metallic base colors"), decoded to linear here:
    // gold (255, 220, 157), silver (250, 249, 245), platinum (214, 209, 200). White gold is
    // a gold-palladium alloy: palladium's linear F0 from Adobe's Standard Material metal
    // references (Pd, 0.7363, 0.7023, 0.6602).
    switch (metal) {
        case Metal::yellow_gold:
            return {1.000f, 0.716f, 0.337f};
        case Metal::white_gold:
            return {0.736f, 0.702f, 0.660f};
        case Metal::platinum:
            return {0.672f, 0.638f, 0.578f};
        case Metal::silver:
            return {0.956f, 0.947f, 0.913f};
    }
    return glm::vec3(1.0f);
}

}  // namespace gem
