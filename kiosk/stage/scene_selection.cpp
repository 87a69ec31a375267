#include "stage/scene_selection.hpp"

#include <cassert>

namespace gem::kiosk {

namespace {

// The same manifest entry: its name and the files it is drawn from.
bool same_entry(const CatalogueStone& a, const CatalogueStone& b) {
    return a.name == b.name && a.database == b.database && a.design == b.design &&
           a.piece == b.piece && a.ring_obj == b.ring_obj;
}

}  // namespace

SceneSelection::SceneSelection(std::vector<BackgroundPreset> backgrounds,
                               std::vector<LightingPreset> lightings)
    : backgrounds_(std::move(backgrounds)), lightings_(std::move(lightings)) {
    // The config loader fills in the built-in sets when a file lists none.
    if (backgrounds_.empty()) backgrounds_ = default_backgrounds();
    if (lightings_.empty()) lightings_ = default_lightings();
    assert(!backgrounds_.empty() && !lightings_.empty());
}

void SceneSelection::set_catalogue(const Catalogue& catalogue) {
    stones_ = catalogue.stones;
    stone_ = 0;
    apply_stone_presets();
}

bool SceneSelection::complete_catalogue(const Catalogue& whole) {
    const bool kept = stone_ < stones_.size() && stone_ < whole.stones.size() &&
                      same_entry(stones_[stone_], whole.stones[stone_]);
    stones_ = whole.stones;
    if (!kept) {
        stone_ = 0;
        apply_stone_presets();
    }
    return kept;
}

void SceneSelection::next_stone() {
    if (stones_.empty()) return;
    stone_ = (stone_ + 1) % stones_.size();
    apply_stone_presets();
}

void SceneSelection::next_preset() {
    background_ = (background_ + 1) % backgrounds_.size();
    lighting_ = (lighting_ + 1) % lightings_.size();
}

void SceneSelection::apply_stone_presets() {
    if (stones_.empty()) return;
    const CatalogueStone& s = stones_[stone_];
    for (std::size_t i = 0; i < backgrounds_.size(); ++i) {
        if (!s.background.empty() && backgrounds_[i].name == s.background) background_ = i;
    }
    for (std::size_t i = 0; i < lightings_.size(); ++i) {
        if (!s.lighting.empty() && lightings_[i].name == s.lighting) lighting_ = i;
    }
}

LookChoice SceneSelection::look() const {
    const BackgroundPreset& b = background();
    const LightingPreset& l = lighting();
    LookChoice look;
    switch (b.kind) {
        case BackgroundPreset::Kind::studio:
            look.background = LookChoice::Background::studio;
            break;
        case BackgroundPreset::Kind::uniform:
            look.background = LookChoice::Background::uniform;
            break;
        case BackgroundPreset::Kind::colour:
            look.background = LookChoice::Background::colour;
            break;
        case BackgroundPreset::Kind::image:
            look.background = LookChoice::Background::image;
            break;
        case BackgroundPreset::Kind::tent:
            look.background = LookChoice::Background::tent;
            break;
    }
    look.colour = b.colour;
    look.image = b.file;
    look.background_intensity = b.intensity;
    look.exposure_ev = l.exposure_ev;
    // One environment serves as the background and as what the stone refracts, except behind a
    // flat colour: there the preset's intensity is the colour's alone.
    const bool flat_behind =
        b.kind == BackgroundPreset::Kind::colour || b.kind == BackgroundPreset::Kind::tent;
    look.environment_intensity = l.environment_intensity * (flat_behind ? 1.0 : b.intensity);
    for (const PresetLight& p : l.lights) {
        look.lights.push_back(Light{p.position, p.directional, p.colour});
    }
    return look;
}

std::string SceneSelection::describe() const {
    std::string s = has_stone() ? "stone '" + stone().name + "' (" + std::to_string(stone_ + 1) +
                                      "/" + std::to_string(stones_.size()) + ")"
                                : "no stone";
    return s + ", background '" + background().name + "', lighting '" + lighting().name + "'";
}

}  // namespace gem::kiosk
