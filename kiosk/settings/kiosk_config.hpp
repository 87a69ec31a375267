#pragma once
// The kiosk's one configuration file (config/gemkiosk.toml, installed as
// /etc/gemkiosk/gemkiosk.toml), read with toml++. Every key has a default, so an empty file
// gives a working kiosk. A bad value or an unknown key is reported and that key keeps its
// default; a file that cannot be read or is not valid TOML is reported once and the whole file
// is set aside (what stands instead: config_fallback.hpp). Each error names the file, the line
// and the key:
//   gemkiosk.toml:12: display.rotation: expected one of 0, 90, 180, 270

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "display/display_options.hpp"
#include "gestures/gesture_options.hpp"
#include "input/input_options.hpp"
#include "service/log.hpp"
#include "settings/presets.hpp"

namespace gem::kiosk {

inline constexpr const char* kDefaultConfigFile = "/etc/gemkiosk/gemkiosk.toml";

// [render]: how the stone is shaded (docs/design.md, "Methods side by side").
// method: a stone method by its name in the registry (gpu/stone_method.hpp), or "auto": the
// most accurate of trace, table blend, table nearest, table one level lower and phong that
// holds the frame rate, measured at start (probe/method_probe.hpp).
inline constexpr const char* kAutoMethod = "auto";

struct RenderConfig {
    std::string method = kAutoMethod;
    bool blend = false;        // table: blend the two nearest stored views, else the nearest
    int cube_face = 256;       // virtual-cube face size, texels
    int depth = 8;             // trace: internal ray segments followed per branch
    int view_cache_mb = 256;   // table: memory for decoded views
    double frame_rate_hz = 0;  // frames drawn per second at most; 0: every refresh
    // auto: the share of a frame period the stone may take (the rest is left for compositing,
    // presenting and the odd slow frame).
    double auto_headroom = 0.8;
};

// [picture]: from the scene's radiance to the display (engine/gpu/hdr_picture.hpp).
enum class PictureTone { neutral, clip };
struct PictureConfig {
    int msaa = 4;                             // samples per pixel of the stone's and ring's edges
    double glare = 0.04;                      // share of the picture spread as glare; 0: none
    PictureTone tone = PictureTone::neutral;  // Khronos PBR Neutral, or a plain clip
    double exposure_ev = 0.0;                 // stops, added to each lighting preset's own
    // While the view is still its frames are averaged, a sub-pixel apart, for still_seconds or
    // until there are still_frames of them (gpu/still_schedule.hpp).
    int still_frames = 1024;
    double still_seconds = 20.0;  // 0: until still_frames
    // A convex stone's fire in still frames: each traces its own wavelengths, one per channel,
    // so the still picture comes to the spectral truth (gpu/hdr_picture.hpp).
    bool spectral_stills = true;
    // The depth the trace follows in still frames where deeper than render.depth (0: as
    // moving). A ray cut at
    // its depth loses the light it still carries, most in a diamond; still frames cost latency
    // while the view settles, not frame rate.
    int still_depth = 16;
    // ... deeper as they accumulate, to this (doubled each time the frames double) ...
    int still_depth_max = 64;
    // A still frame expected to take longer than this (ms) is drawn in bands, one a display
    // frame: what a touch waits for (0: whole, whatever it costs).
    double still_frame_ms = 100.0;
    // Start view: the girdle's width as a share of the picture's height, as far as the whole
    // ring still fits (stage/framing.hpp).
    double stone_share = 0.25;
};

// [catalogue]: where catalogues live and arrive (the main program hands these to the catalogue
// module's own CatalogueOptions, catalogue/catalogue.hpp).
struct CatalogueConfig {
    // The catalogue shipped with the kiosk, shown until staff install one (and whenever the
    // installed one, state_dir/current, is missing or damaged).
    std::filesystem::path default_dir = "/usr/share/gemkiosk/catalogue";
    std::filesystem::path state_dir = "/var/lib/gemkiosk";        // kiosk's own state
    std::filesystem::path inbox_dir = "/var/lib/gemkiosk/inbox";  // new catalogues land here
    // Also watched: catalogue packages' folder (gemtables package), a USB stick's mount point.
    std::vector<std::filesystem::path> watch_dirs = {"/usr/share/gemkiosk/catalogues"};
    double settle_s = 5.0;  // a new catalogue is read once its files stop changing this long
    // Public keys (minisign's .pub files) a delivered catalogue must be signed with; none:
    // catalogues are not authenticated (catalogue/catalogue_signature.hpp).
    std::vector<std::filesystem::path> trusted_keys;
    // The trusted_keys line was there but wrong: signatures are still required (with no key,
    // every delivery is refused) rather than dropped by a typo.
    bool trusted_keys_unreadable = false;
};

// [designs]: tables for catalogue stones that name a design instead of a database
// (builds/design_tables.hpp). A design is shown at once by the trace; its tables are built by
// `builder` in the background, at idle CPU priority and with bounded memory, into
// state_dir/tables, and reused after a restart.
enum class DesignTablesMode { automatic, always, never };
const char* to_string(DesignTablesMode mode);
struct DesignsConfig {
    // automatic ("auto"): built when the trace's frames miss the frame budget, and kept when
    // the tables then draw faster; always: built for every design shown and used; never.
    DesignTablesMode tables = DesignTablesMode::automatic;
    std::filesystem::path builder = "/usr/bin/gemtables";
    int level_px = 256;        // the finest table side; a level of half that is stored too
    double spacing_deg = 6.0;  // between stored views
    int depth = 8;             // internal ray segments stored per pixel
    double threshold = 1e-3;   // exit rays lighter than this are dropped
    int memory_mb = 1024;      // the builder's address space at most
    int jobs = 0;              // tracing threads; 0: every core
};

// [snapshot]: PNG pictures of the screen (CI, remote support).
struct SnapshotConfig {
    std::filesystem::path dir = "/var/lib/gemkiosk/snapshots";
    int every_n_frames = 0;  // headless: a snapshot every n-th frame; 0: none
};

struct KioskConfig {
    DisplayOptions display;
    InputOptions input;
    GestureOptions gestures;  // [gestures] and [attract]
    RenderConfig render;
    PictureConfig picture;
    CatalogueConfig catalogue;
    DesignsConfig designs;
    SnapshotConfig snapshot;
    std::vector<BackgroundPreset> backgrounds = default_backgrounds();
    std::vector<LightingPreset> lightings = default_lightings();
    LogLevel log_level = LogLevel::info;
    double crossfade_s = 0.4;  // cross-fade when a preset or stone changes; 0: a cut
};

struct ConfigLoad {
    KioskConfig config;
    std::vector<std::string> errors;  // in the order of the file's lines
    // False when the file could not be read or is not TOML: `config` is then the defaults and
    // `errors` holds the one line saying why ("gemkiosk.toml:143:10: ...").
    bool parsed = true;
};

// Reads `file`; relative paths in it are taken relative to the file's folder.
ConfigLoad load_config(const std::filesystem::path& file);
// The same from text: `name` is the file name errors carry, `base_dir` resolves relative paths.
ConfigLoad parse_config(std::string_view text, std::string_view name,
                        const std::filesystem::path& base_dir);

// Every key the loader reads, dotted from the top of the file ("display.rotation",
// "lighting.light.colour"); the listing comes from the same tables the loader dispatches on.
std::vector<std::string> known_config_keys();

}  // namespace gem::kiosk
