#pragma once
// Private to the settings library: the top-level tables of the config file, each with the
// function that reads it into the KioskConfig and the function that lists its keys. The
// loader dispatches on these lists and known_config_keys() is made from them, so a key the
// loader reads is always a key it lists.

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "settings/config_reader.hpp"
#include "settings/kiosk_config.hpp"

namespace gem::kiosk {

struct SectionSpec {
    std::string_view name;
    void (*read)(ConfigReader& reader, const toml::node& value, KioskConfig& config);
    void (*list_keys)(std::vector<std::string>& keys);
};

// [display], [input], [gestures], [attract], [render], [catalogue], [designs], [snapshot].
std::span<const SectionSpec> option_sections();
// [[background]], [[lighting]] (with [[lighting.light]]).
std::span<const SectionSpec> preset_sections();

}  // namespace gem::kiosk
