// The option tables of the config file: [display], [input], [gestures], [attract], [render],
// [catalogue], [designs], [snapshot]. Each key is one line of a spec table; the ranges are what the
// kiosk can use, so a value outside them is a typo or a misunderstanding worth a message.
#include <cassert>
#include <charconv>
#include <optional>
#include <string_view>
#include <vector>

#include "gpu/stone_method.hpp"
#include "settings/config_sections.hpp"

namespace gem::kiosk {

namespace {

using Node = toml::node;
using Key = std::string_view;

// "1920x1080" or "1920x1080@60" (the names xrandr and the kernel's video= option use,
// Documentation/fb/modedb.rst).
bool valid_mode(std::string_view text) {
    auto parse_int = [](std::string_view& rest, int& out) {
        const auto [end, ec] = std::from_chars(rest.data(), rest.data() + rest.size(), out);
        if (ec != std::errc() || end == rest.data() || out <= 0) return false;
        rest.remove_prefix(static_cast<std::size_t>(end - rest.data()));
        return true;
    };
    int width = 0, height = 0, rate = 0;
    if (!parse_int(text, width) || text.empty() || text.front() != 'x') return false;
    text.remove_prefix(1);
    if (!parse_int(text, height)) return false;
    if (text.empty()) return true;
    if (text.front() != '@') return false;
    text.remove_prefix(1);
    return parse_int(text, rate) && text.empty();
}

constexpr int kMaxPixels = 16384;  // larger than any scanout or texture the kiosk can use

constexpr KeySpec<DisplayOptions> kDisplayKeys[] = {
    {"backend",
     [](ConfigReader& r, const Node& n, Key k, DisplayOptions& o) {
         std::size_t i = 0;
         if (r.choice(n, k, {"drm", "headless"}, i)) o.backend = i == 0 ? "drm" : "headless";
     }},
    {"device",
     [](ConfigReader& r, const Node& n, Key k, DisplayOptions& o) { r.string(n, k, o.device); }},
    {"connector",
     [](ConfigReader& r, const Node& n, Key k, DisplayOptions& o) { r.string(n, k, o.connector); }},
    {"mode",
     [](ConfigReader& r, const Node& n, Key k, DisplayOptions& o) {
         std::string mode;
         if (!r.string(n, k, mode)) return;
         if (!mode.empty() && !valid_mode(mode)) {
             r.error(n, k,
                     "expected \"WIDTHxHEIGHT\" or \"WIDTHxHEIGHT@HZ\", e.g. \"1920x1080@60\"");
             return;
         }
         o.mode = mode;
     }},
    {"rotation",
     [](ConfigReader& r, const Node& n, Key k, DisplayOptions& o) {
         r.integer_of(n, k, {0, 90, 180, 270}, o.rotation_deg);
     }},
    {"atomic",
     [](ConfigReader& r, const Node& n, Key k, DisplayOptions& o) { r.boolean(n, k, o.atomic); }},
    {"flip_timeout_ms", [](ConfigReader& r, const Node& n, Key k,
                           DisplayOptions& o) { r.integer(n, k, 1, 10000, o.flip_timeout_ms); }},
    {"headless_width", [](ConfigReader& r, const Node& n, Key k,
                          DisplayOptions& o) { r.integer(n, k, 1, kMaxPixels, o.headless_width); }},
    {"headless_height",
     [](ConfigReader& r, const Node& n, Key k, DisplayOptions& o) {
         r.integer(n, k, 1, kMaxPixels, o.headless_height);
     }},
    {"headless_rate_hz",
     [](ConfigReader& r, const Node& n, Key k, DisplayOptions& o) {
         r.number(n, k, 0.0, 1000.0, o.headless_rate_hz);
     }},
};

constexpr KeySpec<InputOptions> kInputKeys[] = {
    {"device_dir",
     [](ConfigReader& r, const Node& n, Key k, InputOptions& o) {
         std::string dir;
         if (!r.string(n, k, dir)) return;
         if (dir.empty()) {
             r.error(n, k, "expected a folder, not an empty string");
             return;
         }
         o.device_dir = dir;
     }},
    {"devices",
     [](ConfigReader& r, const Node& n, Key k, InputOptions& o) { r.strings(n, k, o.devices); }},
    {"calibration", [](ConfigReader& r, const Node& n, Key k,
                       InputOptions& o) { r.numbers(n, k, o.calibration); }},
    {"rotation",
     [](ConfigReader& r, const Node& n, Key k, InputOptions& o) {
         // "display" (-1 in InputOptions): the touch layer turns with the panel.
         if (n.value<std::string_view>() == "display") {
             o.rotation_deg = -1;
             return;
         }
         const std::optional<long long> deg = n.is_integer() ? n.value<long long>() : std::nullopt;
         if (deg != 0 && deg != 90 && deg != 180 && deg != 270) {
             r.error(n, k, "expected \"display\" or one of 0, 90, 180, 270");
             return;
         }
         o.rotation_deg = static_cast<int>(*deg);
     }},
};

void read_tap(ConfigReader& r, const Node& n, Key k, TapAction& action) {
    std::size_t i = 0;
    if (!r.choice(n, k, {"none", "next_stone", "next_preset"}, i)) return;
    constexpr TapAction actions[] = {TapAction::none, TapAction::next_stone,
                                     TapAction::next_preset};
    action = actions[i];
}

constexpr KeySpec<GestureOptions> kGestureKeys[] = {
    {"degrees_per_picture_height",
     [](ConfigReader& r, const Node& n, Key k, GestureOptions& o) {
         r.number(n, k, 1.0, 3600.0, o.degrees_per_picture_height);
     }},
    {"inertia_half_life_s",
     [](ConfigReader& r, const Node& n, Key k, GestureOptions& o) {
         r.number(n, k, 0.0, 60.0, o.inertia_half_life_s);
     }},
    {"min_zoom", [](ConfigReader& r, const Node& n, Key k,
                    GestureOptions& o) { r.positive(n, k, o.min_zoom); }},
    {"max_zoom", [](ConfigReader& r, const Node& n, Key k,
                    GestureOptions& o) { r.positive(n, k, o.max_zoom); }},
    {"wheel_zoom_step", [](ConfigReader& r, const Node& n, Key k,
                           GestureOptions& o) { r.number(n, k, 1.0, 10.0, o.wheel_zoom_step); }},
    {"tap",
     [](ConfigReader& r, const Node& n, Key k, GestureOptions& o) { read_tap(r, n, k, o.tap); }},
    {"two_finger_tap", [](ConfigReader& r, const Node& n, Key k,
                          GestureOptions& o) { read_tap(r, n, k, o.two_finger_tap); }},
    {"tap_max_s", [](ConfigReader& r, const Node& n, Key k,
                     GestureOptions& o) { r.number(n, k, 0.01, 5.0, o.tap_max_s); }},
    {"tap_max_move_px", [](ConfigReader& r, const Node& n, Key k,
                           GestureOptions& o) { r.number(n, k, 0.0, 1000.0, o.tap_max_move_px); }},
    {"fling_window_s", [](ConfigReader& r, const Node& n, Key k,
                          GestureOptions& o) { r.number(n, k, 0.01, 1.0, o.fling_window_s); }},
    {"fling_min_deg_per_s",
     [](ConfigReader& r, const Node& n, Key k, GestureOptions& o) {
         r.number(n, k, 0.0, 3600.0, o.fling_min_deg_per_s);
     }},
    {"fling_max_deg_per_s",
     [](ConfigReader& r, const Node& n, Key k, GestureOptions& o) {
         r.number(n, k, 1.0, 36000.0, o.fling_max_deg_per_s);
     }},
};

constexpr KeySpec<GestureOptions> kAttractKeys[] = {
    {"idle_s", [](ConfigReader& r, const Node& n, Key k,
                  GestureOptions& o) { r.number(n, k, 0.0, 86400.0, o.idle_s); }},
    {"deg_per_s", [](ConfigReader& r, const Node& n, Key k,
                     GestureOptions& o) { r.number(n, k, -360.0, 360.0, o.attract_deg_per_s); }},
    {"preset_s", [](ConfigReader& r, const Node& n, Key k,
                    GestureOptions& o) { r.number(n, k, 0.0, 86400.0, o.attract_preset_s); }},
    {"stone_s", [](ConfigReader& r, const Node& n, Key k,
                   GestureOptions& o) { r.number(n, k, 0.0, 86400.0, o.attract_stone_s); }},
    {"elevation_deg",
     [](ConfigReader& r, const Node& n, Key k, GestureOptions& o) {
         r.number(n, k, -90.0, 90.0, o.attract_elevation_deg);
     }},
    {"ease_s", [](ConfigReader& r, const Node& n, Key k,
                  GestureOptions& o) { r.number(n, k, 0.0, 600.0, o.attract_ease_s); }},
};

constexpr KeySpec<RenderConfig> kRenderKeys[] = {
    {"method",
     [](ConfigReader& r, const Node& n, Key k, RenderConfig& o) {
         // The registry's methods, then "auto".
         std::vector<std::string_view> names;
         for (const gpu::MethodEntry* m : gpu::stone_methods()) names.push_back(m->name);
         names.push_back(kAutoMethod);
         std::size_t i = 0;
         if (!r.choice(n, k, names, i)) return;
         o.method = std::string(names[i]);
     }},
    {"blend",
     [](ConfigReader& r, const Node& n, Key k, RenderConfig& o) { r.boolean(n, k, o.blend); }},
    {"cube_face", [](ConfigReader& r, const Node& n, Key k,
                     RenderConfig& o) { r.integer(n, k, 16, 4096, o.cube_face); }},
    {"depth", [](ConfigReader& r, const Node& n, Key k,
                 RenderConfig& o) { r.integer(n, k, 1, 64, o.depth); }},
    {"view_cache_mb", [](ConfigReader& r, const Node& n, Key k,
                         RenderConfig& o) { r.integer(n, k, 16, 65536, o.view_cache_mb); }},
    {"frame_rate_hz", [](ConfigReader& r, const Node& n, Key k,
                         RenderConfig& o) { r.number(n, k, 0.0, 1000.0, o.frame_rate_hz); }},
    {"auto_headroom", [](ConfigReader& r, const Node& n, Key k,
                         RenderConfig& o) { r.number(n, k, 0.1, 1.0, o.auto_headroom); }},
};

constexpr KeySpec<PictureConfig> kPictureKeys[] = {
    {"msaa", [](ConfigReader& r, const Node& n, Key k,
                PictureConfig& o) { r.integer(n, k, 1, 16, o.msaa); }},
    {"glare", [](ConfigReader& r, const Node& n, Key k,
                 PictureConfig& o) { r.number(n, k, 0.0, 1.0, o.glare); }},
    {"tone",
     [](ConfigReader& r, const Node& n, Key k, PictureConfig& o) {
         std::size_t i = 0;
         if (!r.choice(n, k, {"neutral", "clip"}, i)) return;
         o.tone = i == 0 ? PictureTone::neutral : PictureTone::clip;
     }},
    {"exposure_ev", [](ConfigReader& r, const Node& n, Key k,
                       PictureConfig& o) { r.number(n, k, -16.0, 16.0, o.exposure_ev); }},
    {"still_frames", [](ConfigReader& r, const Node& n, Key k,
                        PictureConfig& o) { r.integer(n, k, 1, 1024, o.still_frames); }},
    {"spectral_stills", [](ConfigReader& r, const Node& n, Key k,
                           PictureConfig& o) { r.boolean(n, k, o.spectral_stills); }},
    {"still_depth", [](ConfigReader& r, const Node& n, Key k,
                       PictureConfig& o) { r.integer(n, k, 0, 64, o.still_depth); }},
    {"still_seconds", [](ConfigReader& r, const Node& n, Key k,
                         PictureConfig& o) { r.number(n, k, 0.0, 600.0, o.still_seconds); }},
    {"still_depth_max", [](ConfigReader& r, const Node& n, Key k,
                           PictureConfig& o) { r.integer(n, k, 0, 64, o.still_depth_max); }},
    {"still_frame_ms", [](ConfigReader& r, const Node& n, Key k,
                          PictureConfig& o) { r.number(n, k, 0.0, 10000.0, o.still_frame_ms); }},
    {"stone_share", [](ConfigReader& r, const Node& n, Key k,
                       PictureConfig& o) { r.number(n, k, 0.05, 0.8, o.stone_share); }},
};

constexpr KeySpec<CatalogueConfig> kCatalogueKeys[] = {
    {"default_dir", [](ConfigReader& r, const Node& n, Key k,
                       CatalogueConfig& o) { r.path(n, k, o.default_dir); }},
    {"state_dir",
     [](ConfigReader& r, const Node& n, Key k, CatalogueConfig& o) { r.path(n, k, o.state_dir); }},
    {"inbox_dir",
     [](ConfigReader& r, const Node& n, Key k, CatalogueConfig& o) { r.path(n, k, o.inbox_dir); }},
    {"watch_dirs", [](ConfigReader& r, const Node& n, Key k,
                      CatalogueConfig& o) { r.paths(n, k, o.watch_dirs); }},
    {"settle_s", [](ConfigReader& r, const Node& n, Key k,
                    CatalogueConfig& o) { r.number(n, k, 0.0, 3600.0, o.settle_s); }},
    {"trusted_keys",
     [](ConfigReader& r, const Node& n, Key k, CatalogueConfig& o) {
         if (!r.paths(n, k, o.trusted_keys)) o.trusted_keys_unreadable = true;
     }},
};

constexpr KeySpec<DesignsConfig> kDesignsKeys[] = {
    {"tables",
     [](ConfigReader& r, const Node& n, Key k, DesignsConfig& o) {
         std::size_t i = 0;
         if (!r.choice(n, k, {"auto", "always", "never"}, i)) return;
         constexpr DesignTablesMode modes[] = {DesignTablesMode::automatic,
                                               DesignTablesMode::always, DesignTablesMode::never};
         o.tables = modes[i];
     }},
    {"builder",
     [](ConfigReader& r, const Node& n, Key k, DesignsConfig& o) { r.path(n, k, o.builder); }},
    {"level_px", [](ConfigReader& r, const Node& n, Key k,
                    DesignsConfig& o) { r.integer(n, k, 16, 4096, o.level_px); }},
    {"spacing_deg", [](ConfigReader& r, const Node& n, Key k,
                       DesignsConfig& o) { r.number(n, k, 0.5, 45.0, o.spacing_deg); }},
    {"depth", [](ConfigReader& r, const Node& n, Key k,
                 DesignsConfig& o) { r.integer(n, k, 1, 64, o.depth); }},
    {"threshold", [](ConfigReader& r, const Node& n, Key k,
                     DesignsConfig& o) { r.number(n, k, 0.0, 0.5, o.threshold); }},
    {"memory_mb", [](ConfigReader& r, const Node& n, Key k,
                     DesignsConfig& o) { r.integer(n, k, 16, 1 << 20, o.memory_mb); }},
    {"jobs", [](ConfigReader& r, const Node& n, Key k,
                DesignsConfig& o) { r.integer(n, k, 0, 1024, o.jobs); }},
};

constexpr KeySpec<SnapshotConfig> kSnapshotKeys[] = {
    {"dir", [](ConfigReader& r, const Node& n, Key k, SnapshotConfig& o) { r.path(n, k, o.dir); }},
    {"every_n_frames", [](ConfigReader& r, const Node& n, Key k,
                          SnapshotConfig& o) { r.integer(n, k, 0, 1000000, o.every_n_frames); }},
};

// Zoom limits must be ordered; when they are not, the pair goes back to its defaults (which
// are) and the message points at max_zoom's line, or min_zoom's when only that one is set.
void check_zoom_order(ConfigReader& r, const Node& node, GestureOptions& o) {
    if (o.min_zoom <= o.max_zoom) return;
    const toml::table& table = *node.as_table();
    const toml::node* at = table.get("max_zoom");
    if (at == nullptr) at = table.get("min_zoom");
    assert(at != nullptr);  // the defaults are ordered, so one of the two was set
    r.error(*at, "gestures.max_zoom",
            "must not be less than gestures.min_zoom; both keep their defaults");
    const GestureOptions defaults;
    o.min_zoom = defaults.min_zoom;
    o.max_zoom = defaults.max_zoom;
}

constexpr SectionSpec kSections[] = {
    {"display",
     [](ConfigReader& r, const Node& n, KioskConfig& c) {
         read_table<DisplayOptions>(r, n, "display", kDisplayKeys, c.display);
     },
     [](std::vector<std::string>& keys) { append_keys(keys, "display", kDisplayKeys); }},
    {"input",
     [](ConfigReader& r, const Node& n, KioskConfig& c) {
         read_table<InputOptions>(r, n, "input", kInputKeys, c.input);
     },
     [](std::vector<std::string>& keys) { append_keys(keys, "input", kInputKeys); }},
    {"gestures",
     [](ConfigReader& r, const Node& n, KioskConfig& c) {
         read_table<GestureOptions>(r, n, "gestures", kGestureKeys, c.gestures);
         if (n.is_table()) check_zoom_order(r, n, c.gestures);
     },
     [](std::vector<std::string>& keys) { append_keys(keys, "gestures", kGestureKeys); }},
    {"attract",
     [](ConfigReader& r, const Node& n, KioskConfig& c) {
         read_table<GestureOptions>(r, n, "attract", kAttractKeys, c.gestures);
     },
     [](std::vector<std::string>& keys) { append_keys(keys, "attract", kAttractKeys); }},
    {"render",
     [](ConfigReader& r, const Node& n, KioskConfig& c) {
         read_table<RenderConfig>(r, n, "render", kRenderKeys, c.render);
     },
     [](std::vector<std::string>& keys) { append_keys(keys, "render", kRenderKeys); }},
    {"picture",
     [](ConfigReader& r, const Node& n, KioskConfig& c) {
         read_table<PictureConfig>(r, n, "picture", kPictureKeys, c.picture);
     },
     [](std::vector<std::string>& keys) { append_keys(keys, "picture", kPictureKeys); }},
    {"catalogue",
     [](ConfigReader& r, const Node& n, KioskConfig& c) {
         read_table<CatalogueConfig>(r, n, "catalogue", kCatalogueKeys, c.catalogue);
     },
     [](std::vector<std::string>& keys) { append_keys(keys, "catalogue", kCatalogueKeys); }},
    {"designs",
     [](ConfigReader& r, const Node& n, KioskConfig& c) {
         read_table<DesignsConfig>(r, n, "designs", kDesignsKeys, c.designs);
     },
     [](std::vector<std::string>& keys) { append_keys(keys, "designs", kDesignsKeys); }},
    {"snapshot",
     [](ConfigReader& r, const Node& n, KioskConfig& c) {
         read_table<SnapshotConfig>(r, n, "snapshot", kSnapshotKeys, c.snapshot);
     },
     [](std::vector<std::string>& keys) { append_keys(keys, "snapshot", kSnapshotKeys); }},
};

}  // namespace

std::span<const SectionSpec> option_sections() {
    return kSections;
}

}  // namespace gem::kiosk
