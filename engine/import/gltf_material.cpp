// A glTF material's factors and the extensions that say what it is made of: the
// metallic-roughness model's, Khronos's gem and surface extensions, and a vendor's gem material
// (WEBGI_materials_diamond). What a piece makes of them is piece/gltf_piece.cpp.
#include <limits>
#include <optional>
#include <string>

#include "import/gltf_values.hpp"
#include "optics/colour.hpp"

namespace gem::import {

namespace {

// A colour as web viewers write one: a number 0xRRGGBB (three.js's Color.getHex()), a string
// "#RRGGBB", or a list or an {r, g, b} object of 0–1 components; the first two are sRGB, the
// last two linear, as three.js keeps them. Empty when it is none of these.
std::optional<glm::dvec3> web_colour(const tinygltf::Value& v) {
    const auto from_hex = [](unsigned long rgb) {
        return glm::dvec3(srgb_decode(double((rgb >> 16) & 0xFF) / 255.0),
                          srgb_decode(double((rgb >> 8) & 0xFF) / 255.0),
                          srgb_decode(double(rgb & 0xFF) / 255.0));
    };
    if (v.IsNumber()) {
        const double x = v.GetNumberAsDouble();
        if (!(x >= 0.0 && x <= double(0xFFFFFF))) return std::nullopt;
        return from_hex(static_cast<unsigned long>(x));
    }
    if (v.IsString()) {
        std::string t = v.Get<std::string>();
        if (!t.empty() && t[0] == '#') t.erase(0, 1);
        if (t.size() != 6 || t.find_first_not_of("0123456789abcdefABCDEF") != std::string::npos) {
            return std::nullopt;
        }
        return from_hex(std::stoul(t, nullptr, 16));
    }
    glm::dvec3 c(0.0);
    if (v.IsArray() && v.ArrayLen() >= 3) {
        for (int i = 0; i < 3; ++i) {
            if (!v.Get(i).IsNumber()) return std::nullopt;
            c[i] = v.Get(i).GetNumberAsDouble();
        }
    } else if (v.IsObject() && v.Has("r") && v.Has("g") && v.Has("b")) {
        c = {number(v, "r", -1.0), number(v, "g", -1.0), number(v, "b", -1.0)};
    } else {
        return std::nullopt;
    }
    if (!all_finite(c) || glm::any(glm::lessThan(c, glm::dvec3(0.0)))) return std::nullopt;
    return glm::min(c, glm::dvec3(1.0));
}

// WEBGI_materials_diamond, as the iJewel/WebGi exporters write it (DiamondMaterial's JSON):
// refractiveIndex, dispersion (the per-channel offset of the index), color, and isDiamond,
// which when false says the material is not a gem. Numbers outside what any gem has are left
// out rather than believed.
std::optional<GltfMaterial::VendorGem> vendor_gem_of(const std::string& name,
                                                     const tinygltf::Value& v) {
    if (!v.IsObject()) return GltfMaterial::VendorGem{name, {}, {}, {}};
    if (v.Has("isDiamond") && v.Get("isDiamond").IsBool() && !v.Get("isDiamond").Get<bool>()) {
        return std::nullopt;
    }
    GltfMaterial::VendorGem gem{name, {}, {}, {}};
    const double n = number(v, "refractiveIndex", -1.0);
    if (n >= 1.2 && n <= 3.5) gem.ior = n;
    const double spread = number(v, "dispersion", -1.0);
    if (spread >= 0.0 && spread <= 0.2) gem.spread = spread;
    if (v.Has("color")) gem.colour = web_colour(v.Get("color"));
    return gem;
}

}  // namespace

GltfMaterial material_of(const tinygltf::Material& m) {
    GltfMaterial out;
    out.name = m.name;
    const auto& pbr = m.pbrMetallicRoughness;
    if (pbr.baseColorFactor.size() >= 3) {
        out.base_colour = {pbr.baseColorFactor[0], pbr.baseColorFactor[1], pbr.baseColorFactor[2]};
    }
    out.metallic = pbr.metallicFactor;
    out.roughness = pbr.roughnessFactor;
    for (const auto& [name, value] : m.extensions) {
        out.extensions.push_back(name);
        // Defaults as each extension's specification gives them.
        if (name == "KHR_materials_transmission") {
            out.transmission = number(value, "transmissionFactor", 0.0);
        } else if (name == "KHR_materials_ior") {
            out.ior = number(value, "ior", 1.5);
        } else if (name == "KHR_materials_dispersion") {
            out.dispersion = number(value, "dispersion", 0.0);
        } else if (name == "KHR_materials_volume") {
            out.attenuation_colour = colour(value, "attenuationColor", glm::dvec3(1.0));
            out.attenuation_distance_m =
                number(value, "attenuationDistance", std::numeric_limits<double>::infinity());
            out.thickness_m = number(value, "thicknessFactor", 0.0);
        } else if (name == "KHR_materials_clearcoat") {
            out.clearcoat = number(value, "clearcoatFactor", 0.0);
        } else if (name == "KHR_materials_specular") {
            out.specular = number(value, "specularFactor", 1.0);
            out.specular_colour = colour(value, "specularColorFactor", glm::dvec3(1.0));
        } else if (name == "WEBGI_materials_diamond") {
            out.vendor_gem = vendor_gem_of(name, value);
        }
    }
    return out;
}

}  // namespace gem::import
