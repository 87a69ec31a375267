#pragma once
// Background and lighting presets: what the shopper (two-finger tap) and attract mode cycle
// through, in the order the config file lists them ([[background]], [[lighting]]). A file
// that lists none of a kind gets the built-in set of that kind.

#include <filesystem>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace gem::kiosk {

struct BackgroundPreset {
    // studio: the procedural studio (dark counter, softboxes) all round; uniform: a surround
    // of one radiance `colour`; colour: a flat `colour` behind a studio-lit stone; image: an
    // equirectangular PNG (8-bit sRGB) or Radiance .hdr (linear) environment from `file`;
    // tent: a flat `colour` behind a stone in a white light tent with dark flags (product
    // photography's white look).
    enum class Kind { studio, uniform, colour, image, tent };

    std::string name;
    Kind kind = Kind::studio;
    glm::dvec3 colour{0.05};     // linear RGB; uniform and colour only
    std::filesystem::path file;  // image only; absolute (the loader resolves relative paths)
    double intensity = 1.0;      // scales the background's radiance
};

struct PresetLight {
    // A point light's position (mm, stone frame, docs/design.md, "Contracts"), or for a
    // directional light the direction toward the light (any length but zero).
    glm::dvec3 position{0.0, 100.0, 0.0};
    bool directional = false;
    glm::dvec3 colour{1.0};  // linear RGB intensity
};

// The shading pass takes at most this many lights (engine/scene/lights.hpp, kMaxLights; the
// settings library does not link the engine, so the number is repeated here).
inline constexpr std::size_t kMaxPresetLights = 4;

struct LightingPreset {
    std::string name;
    double environment_intensity = 1.0;  // scales the environment the stone refracts
    double exposure_ev = 0.0;            // the picture's exposure under this lighting, stops
    std::vector<PresetLight> lights;     // at most kMaxPresetLights; none: environment only
};

// The built-in sets, used when the config file has no [[background]] / [[lighting]]; the
// shipped config/gemkiosk.toml writes them out.
std::vector<BackgroundPreset> default_backgrounds();
std::vector<LightingPreset> default_lightings();

const char* to_string(BackgroundPreset::Kind kind);

}  // namespace gem::kiosk
