#pragma once
// Which stone, background and lighting are on screen, and what the next ones are: the kiosk
// cycles stones in catalogue order and presets in config order; a stone that names its own
// background or lighting preset brings it along. The result is a LookChoice for StoneScene.
// The stone shown holds its models (a piece's meshes); the catalogue holds them for its first
// entry only, so the others are built as they come on screen, the next one ahead
// (near_entries.hpp).

#include <cstddef>
#include <string>
#include <vector>

#include "catalogue/catalogue.hpp"
#include "catalogue/near_entries.hpp"
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
    // An entry whose files no longer build (changed or gone since the catalogue was checked)
    // is said in the log and left out; where none builds, there is no stone.
    void next_stone();
    // Background and lighting presets advance together: a preset is one look of the shop.
    void next_preset();

    bool has_stone() const { return !stones_.empty(); }
    const CatalogueStone& stone() const { return shown_; }
    std::size_t stone_index() const { return stone_; }
    const BackgroundPreset& background() const { return backgrounds_[background_]; }
    const LightingPreset& lighting() const { return lightings_[lighting_]; }
    LookChoice look() const;
    std::string describe() const;  // "stone 'ruby' (2/5), background 'studio', lighting 'soft'"

  private:
    // Shows entry `index`, or the first after it that builds.
    void show(std::size_t index);
    // The entry after the one shown, built on a thread of its own for the next tap.
    void build_next_ahead();
    void apply_stone_presets();

    std::vector<BackgroundPreset> backgrounds_;
    std::vector<LightingPreset> lightings_;
    std::vector<CatalogueStone> stones_;  // as the catalogue holds them
    std::size_t stone_ = 0;
    CatalogueStone shown_;  // stones_[stone_] with its models
    NearEntries near_;
    std::size_t background_ = 0;
    std::size_t lighting_ = 0;
};

}  // namespace gem::kiosk
