// [[background]] and [[lighting]] (with its [[lighting.light]]) tables. Presets are kept in
// file order, which is the order the kiosk cycles through them; a file with none of a kind
// keeps the built-in set. Keys that depend on each other (kind and colour or file; position
// and direction) are checked once the whole table is read.
#include <algorithm>
#include <cctype>

#include "settings/config_sections.hpp"

namespace gem::kiosk {

namespace {

using Node = toml::node;
using Key = std::string_view;

struct BackgroundDraft {
    BackgroundPreset preset;
    const Node* name = nullptr;  // set when read: the keys the table gave
    const Node* colour = nullptr;
    const Node* file = nullptr;
};

// The environment loader reads 8-bit PNG and Radiance RGBE (engine/scene/environment.hpp).
bool image_file_name(const std::filesystem::path& file) {
    std::string extension = file.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension == ".png" || extension == ".hdr";
}

void read_name(ConfigReader& r, const Node& n, Key k, std::string& name, const Node*& at) {
    std::string text;
    if (!r.string(n, k, text)) return;
    if (text.empty()) {
        r.error(n, k, "must not be empty");
        return;
    }
    name = text;
    at = &n;
}

constexpr KeySpec<BackgroundDraft> kBackgroundKeys[] = {
    {"name", [](ConfigReader& r, const Node& n, Key k,
                BackgroundDraft& d) { read_name(r, n, k, d.preset.name, d.name); }},
    {"kind",
     [](ConfigReader& r, const Node& n, Key k, BackgroundDraft& d) {
         std::size_t i = 0;
         if (!r.choice(n, k, {"studio", "uniform", "colour", "image", "tent"}, i)) return;
         constexpr BackgroundPreset::Kind kinds[] = {
             BackgroundPreset::Kind::studio, BackgroundPreset::Kind::uniform,
             BackgroundPreset::Kind::colour, BackgroundPreset::Kind::image,
             BackgroundPreset::Kind::tent};
         d.preset.kind = kinds[i];
     }},
    {"colour",
     [](ConfigReader& r, const Node& n, Key k, BackgroundDraft& d) {
         if (r.colour(n, k, d.preset.colour)) d.colour = &n;
     }},
    {"file",
     [](ConfigReader& r, const Node& n, Key k, BackgroundDraft& d) {
         std::filesystem::path file;
         if (!r.path(n, k, file)) return;
         if (!image_file_name(file)) {
             r.error(n, k, "expected a PNG (.png) or Radiance (.hdr) image");
             return;
         }
         d.preset.file = file;
         d.file = &n;
     }},
    {"intensity", [](ConfigReader& r, const Node& n, Key k,
                     BackgroundDraft& d) { r.number(n, k, 0.0, 1000.0, d.preset.intensity); }},
};

// A preset without a usable name is still kept (cycling does not need names), named by its
// place in the file.
void finish_name(ConfigReader& r, const Node& table, std::string_view what, std::size_t index,
                 const Node* name_node, std::string& name,
                 const std::vector<std::string>& earlier) {
    const std::string fallback = std::string(what) + " " + std::to_string(index + 1);
    if (name_node == nullptr) {
        if (table.as_table()->get("name") == nullptr) {
            r.error(table, std::string(what) + ".name", "missing; called \"" + fallback + "\"");
        }
        name = fallback;
        return;
    }
    if (std::find(earlier.begin(), earlier.end(), name) != earlier.end()) {
        r.error(*name_node, std::string(what) + ".name",
                "\"" + name + "\" names an earlier " + std::string(what) + " too; called \"" +
                    fallback + "\"");
        name = fallback;
    }
}

void finish_background(ConfigReader& r, const Node& table, BackgroundDraft& d, std::size_t index,
                       const std::vector<std::string>& earlier) {
    using Kind = BackgroundPreset::Kind;
    BackgroundPreset& p = d.preset;
    finish_name(r, table, "background", index, d.name, p.name, earlier);
    if (p.kind == Kind::image && d.file == nullptr) {
        if (table.as_table()->get("file") == nullptr) {
            r.error(table, "background.file", "kind \"image\" needs a file; shown as \"studio\"");
        }
        p.kind = Kind::studio;
    }
    if (p.kind != Kind::image && d.file != nullptr) {
        r.error(*d.file, "background.file", "only kind \"image\" uses a file");
        p.file.clear();
    }
    const bool coloured = p.kind == Kind::uniform || p.kind == Kind::colour || p.kind == Kind::tent;
    if (!coloured && d.colour != nullptr) {
        r.error(*d.colour, "background.colour",
                "only kinds \"uniform\", \"colour\" and \"tent\" use a colour");
    }
    // Without a colour, a uniform surround and a tent's backdrop are white (as a scene's
    // [environment] is) and a flat background is the near-black of BackgroundPreset's default.
    if (d.colour == nullptr || !coloured) {
        p.colour = p.kind == Kind::uniform || p.kind == Kind::tent ? glm::dvec3(1.0)
                                                                   : BackgroundPreset{}.colour;
    }
}

struct LightDraft {
    PresetLight light;
    glm::dvec3 position{0.0};
    glm::dvec3 direction{0.0};
    const Node* position_at = nullptr;  // set when read
    const Node* direction_at = nullptr;
};

constexpr KeySpec<LightDraft> kLightKeys[] = {
    {"position",
     [](ConfigReader& r, const Node& n, Key k, LightDraft& d) {
         if (r.vec3(n, k, d.position)) d.position_at = &n;
     }},
    {"direction",
     [](ConfigReader& r, const Node& n, Key k, LightDraft& d) {
         glm::dvec3 v(0.0);
         if (!r.vec3(n, k, v)) return;
         if (v == glm::dvec3(0.0)) {
             r.error(n, k, "must not be [0, 0, 0]");
             return;
         }
         d.direction = v;
         d.direction_at = &n;
     }},
    {"colour",
     [](ConfigReader& r, const Node& n, Key k, LightDraft& d) { r.colour(n, k, d.light.colour); }},
};

void finish_light(ConfigReader& r, const Node& table, LightDraft& d) {
    if (d.position_at != nullptr) {
        d.light.position = d.position;
        if (d.direction_at != nullptr) {
            r.error(*d.direction_at, "lighting.light.direction",
                    "a light has a position or a direction, not both; the position is used");
        }
    } else if (d.direction_at != nullptr) {
        d.light.position = d.direction;
        d.light.directional = true;
    } else {
        const toml::table& t = *table.as_table();
        if (t.get("position") == nullptr && t.get("direction") == nullptr) {
            r.error(table, "lighting.light",
                    "needs a position or a direction; placed at [0, 100, 0]");
        }
    }
}

struct LightingDraft {
    LightingPreset preset;
    const Node* name = nullptr;
};

void read_lights(ConfigReader& r, const Node& n, Key k, LightingDraft& d) {
    const toml::array* array = n.as_array();
    if (array == nullptr || !(array->empty() || array->is_array_of_tables())) {
        r.error(n, k, "expected [[lighting.light]] tables");
        return;
    }
    std::vector<PresetLight> lights;
    for (const Node& item : *array) {
        if (lights.size() == kMaxPresetLights) {
            r.error(item, k,
                    "at most " + std::to_string(kMaxPresetLights) +
                        " lights in a preset; this one is left out");
            continue;
        }
        LightDraft light;
        read_table<LightDraft>(r, item, k, kLightKeys, light);
        finish_light(r, item, light);
        lights.push_back(light.light);
    }
    d.preset.lights = std::move(lights);
}

constexpr KeySpec<LightingDraft> kLightingKeys[] = {
    {"name", [](ConfigReader& r, const Node& n, Key k,
                LightingDraft& d) { read_name(r, n, k, d.preset.name, d.name); }},
    {"environment_intensity",
     [](ConfigReader& r, const Node& n, Key k, LightingDraft& d) {
         r.number(n, k, 0.0, 1000.0, d.preset.environment_intensity);
     }},
    {"exposure_ev", [](ConfigReader& r, const Node& n, Key k,
                       LightingDraft& d) { r.number(n, k, -16.0, 16.0, d.preset.exposure_ev); }},
    {"light", read_lights},
};

// Reads an array of tables into presets, one Draft per table finished by `finish`; an empty
// array keeps the built-in presets.
template <class Preset, class Draft, class Finish>
void read_presets(ConfigReader& r, const Node& n, std::string_view what,
                  std::span<const KeySpec<Draft>> specs, Finish finish,
                  std::vector<Preset>& presets) {
    const toml::array* array = n.as_array();
    if (array == nullptr || !(array->empty() || array->is_array_of_tables())) {
        r.error(n, what, "expected [[" + std::string(what) + "]] tables");
        return;
    }
    if (array->empty()) return;
    std::vector<Preset> read;
    std::vector<std::string> names;
    for (std::size_t i = 0; i < array->size(); ++i) {
        const Node& table = *array->get(i);
        Draft draft;
        read_table<Draft>(r, table, what, specs, draft);
        finish(r, table, draft, i, names);
        names.push_back(draft.preset.name);
        read.push_back(std::move(draft.preset));
    }
    presets = std::move(read);
}

constexpr SectionSpec kSections[] = {
    {"background",
     [](ConfigReader& r, const Node& n, KioskConfig& c) {
         read_presets<BackgroundPreset, BackgroundDraft>(r, n, "background", kBackgroundKeys,
                                                         finish_background, c.backgrounds);
     },
     [](std::vector<std::string>& keys) { append_keys(keys, "background", kBackgroundKeys); }},
    {"lighting",
     [](ConfigReader& r, const Node& n, KioskConfig& c) {
         auto finish = [](ConfigReader& reader, const Node& table, LightingDraft& d,
                          std::size_t index, const std::vector<std::string>& earlier) {
             finish_name(reader, table, "lighting", index, d.name, d.preset.name, earlier);
         };
         read_presets<LightingPreset, LightingDraft>(r, n, "lighting", kLightingKeys, finish,
                                                     c.lightings);
     },
     [](std::vector<std::string>& keys) {
         append_keys(keys, "lighting", kLightingKeys);
         append_keys(keys, "lighting.light", kLightKeys);
     }},
};

}  // namespace

std::span<const SectionSpec> preset_sections() {
    return kSections;
}

}  // namespace gem::kiosk
