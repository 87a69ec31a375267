#include "settings/presets.hpp"

namespace gem::kiosk {

namespace {

BackgroundPreset background(std::string name, BackgroundPreset::Kind kind, glm::dvec3 colour,
                            double intensity = 1.0) {
    BackgroundPreset preset;
    preset.name = std::move(name);
    preset.kind = kind;
    preset.colour = colour;
    preset.intensity = intensity;
    return preset;
}

PresetLight light(glm::dvec3 position, bool directional, glm::dvec3 colour) {
    PresetLight l;
    l.position = position;
    l.directional = directional;
    l.colour = colour;
    return l;
}

LightingPreset lighting(std::string name, double environment_intensity, double exposure_ev,
                        std::vector<PresetLight> lights) {
    LightingPreset preset;
    preset.name = std::move(name);
    preset.environment_intensity = environment_intensity;
    preset.exposure_ev = exposure_ev;
    preset.lights = std::move(lights);
    return preset;
}

}  // namespace

// The studio is the environment gemrender's scenes default to (config/scenes/README.md);
// the others are the surrounds a jeweller's window uses: black velvet, the white of a web
// shop's product photograph (a light tent; intensity 4 keeps the backdrop white through the
// tone curve), and a warm grey counter.
std::vector<BackgroundPreset> default_backgrounds() {
    using Kind = BackgroundPreset::Kind;
    return {
        background("studio", Kind::studio, glm::dvec3(0.05)),
        background("velvet", Kind::colour, glm::dvec3(0.01, 0.01, 0.012)),
        background("white", Kind::tent, glm::dvec3(1.0), 4.0),
        background("counter", Kind::colour, glm::dvec3(0.18, 0.16, 0.14)),
    };
}

// Positions in mm in the stone frame (y up through the table): a stone a few mm across lit
// from tens of mm away, as by a counter spotlight. The first is the default light of
// gemrender's scenes (config/scenes/default.toml). Each goes with the background of the same
// place (SceneSelection): "two softboxes" lifts the velvet look by a third of a stop, "light
// tent" is the white look's lights overhead, one of them directional.
std::vector<LightingPreset> default_lightings() {
    return {
        lighting("spotlight", 1.0, 0.0, {light({-30.0, 80.0, 45.0}, false, glm::dvec3(2.0))}),
        lighting("two softboxes", 0.8, 0.3,
                 {light({-60.0, 60.0, 30.0}, false, glm::dvec3(1.2)),
                  light({60.0, 60.0, 30.0}, false, glm::dvec3(1.2))}),
        lighting("light tent", 1.0, 0.0,
                 {light({-50.0, 90.0, 40.0}, false, glm::dvec3(1.2)),
                  light({0.4, 1.0, 0.5}, true, glm::dvec3(1.0))}),
        lighting("ambient", 1.5, 0.0, {}),
    };
}

const char* to_string(BackgroundPreset::Kind kind) {
    switch (kind) {
        case BackgroundPreset::Kind::studio:
            return "studio";
        case BackgroundPreset::Kind::uniform:
            return "uniform";
        case BackgroundPreset::Kind::colour:
            return "colour";
        case BackgroundPreset::Kind::image:
            return "image";
        case BackgroundPreset::Kind::tent:
            return "tent";
    }
    return "?";
}

}  // namespace gem::kiosk
