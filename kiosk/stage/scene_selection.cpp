#include "stage/scene_selection.hpp"

#include <cassert>

#include "catalogue/entry_models.hpp"
#include "service/log.hpp"

namespace gem::kiosk {

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
    show(0);
}

bool SceneSelection::complete_catalogue(const Catalogue& whole) {
    const bool kept = stone_ < stones_.size() && stone_ < whole.stones.size() &&
                      same_entry(stones_[stone_], whole.stones[stone_]);
    stones_ = whole.stones;
    if (kept) {
        build_next_ahead();
    } else {
        show(0);
    }
    return kept;
}

void SceneSelection::next_stone() {
    if (stones_.empty()) return;
    show((stone_ + 1) % stones_.size());
}

void SceneSelection::show(std::size_t index) {
    while (!stones_.empty()) {
        const std::size_t i = index % stones_.size();
        Result<CatalogueStone> near = near_.bring(stones_[i]);
        if (near) {
            stone_ = i;
            shown_ = std::move(near).value();
            build_next_ahead();
            apply_stone_presets();
            return;
        }
        // Said once: the entry is gone from the cycle until the catalogue comes again.
        log_error(near.error() +
                  "; left out (its file changed after the catalogue was checked: "
                  "deliver the catalogue again)");
        stones_.erase(stones_.begin() + static_cast<std::ptrdiff_t>(i));
        index = i;
    }
    stone_ = 0;
    shown_ = {};
}

void SceneSelection::build_next_ahead() {
    if (stones_.size() > 1) near_.build_ahead(stones_[(stone_ + 1) % stones_.size()]);
}

void SceneSelection::next_preset() {
    background_ = (background_ + 1) % backgrounds_.size();
    lighting_ = (lighting_ + 1) % lightings_.size();
}

void SceneSelection::apply_stone_presets() {
    if (stones_.empty()) return;
    const CatalogueStone& s = shown_;
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
