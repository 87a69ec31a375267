#pragma once
// Which stone, background and lighting are on screen, and what the next ones are: the kiosk
// cycles stones in catalogue order and presets in config order; a stone that names its own
// background or lighting preset brings it along. The result is a LookChoice for StoneScene.

#include <cstddef>
#include <string>
#include <vector>

#include "catalogue/catalogue.hpp"
#include "settings/presets.hpp"
#include "stage/stone_scene.hpp"

namespace gem::kiosk {

class SceneSelection {
  public:
    SceneSelection(std::vector<BackgroundPreset> backgrounds,
                   std::vector<LightingPreset> lightings);

    // A new catalogue starts at its first stone; the presets stay where they were unless the
    // stone names its own.
    void set_catalogue(const Catalogue& catalogue);
    // The same catalogue with more of its stones checked (CatalogueCompletion): the stone on
    // screen stays where the whole catalogue holds it at the same place; false where it does
    // not (then it starts at the first stone, as a new catalogue).
    bool complete_catalogue(const Catalogue& whole);
    void next_stone();
    // Background and lighting presets advance together: a preset is one look of the shop.
    void next_preset();

    bool has_stone() const { return !stones_.empty(); }
    const CatalogueStone& stone() const { return stones_[stone_]; }
    std::size_t stone_index() const { return stone_; }
    const BackgroundPreset& background() const { return backgrounds_[background_]; }
    const LightingPreset& lighting() const { return lightings_[lighting_]; }
    LookChoice look() const;
    std::string describe() const;  // "stone 'ruby' (2/5), background 'studio', lighting 'soft'"

  private:
    void apply_stone_presets();

    std::vector<BackgroundPreset> backgrounds_;
    std::vector<LightingPreset> lightings_;
    std::vector<CatalogueStone> stones_;
    std::size_t stone_ = 0;
    std::size_t background_ = 0;
    std::size_t lighting_ = 0;
};

}  // namespace gem::kiosk
