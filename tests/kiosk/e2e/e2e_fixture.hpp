#pragma once
// What the kiosk's end-to-end tests share: small catalogues built with the real gemtables, a
// config for a small headless kiosk, the gestures a raw recording holds (read off its E: lines
// here, independently of the kiosk's input code), and reference pictures of a catalogue stone
// at a given view, drawn in this process with the shading stage alone (no input, no gestures,
// no main loop) to compare the kiosk's snapshots with.

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "gemdb/reader.hpp"
#include "gestures/gesture_output.hpp"
#include "picture/image.hpp"
#include "util/result.hpp"

namespace gem::kiosk_e2e {

inline constexpr int kWidth = 200;  // the Atmel panel's 800 × 480, scaled by 1/4
inline constexpr int kHeight = 120;
inline constexpr double kDegreesPerHeight = 180.0;  // the config's gestures gain

// A catalogue of one stone (config/stones/<stone>.toml) in a parametric ring, its database
// built once (64 and 128 px, 10°) under the test artefacts and reused by later tests.
Result<std::filesystem::path> test_catalogue(const std::string& stone);

// A fresh, empty directory for one test under the artefacts.
std::filesystem::path fresh_dir(const std::string& name);

std::string read_text(const std::filesystem::path& file);
void write_text(const std::filesystem::path& file, const std::string& text);
// The line of the kiosk's `log` holding `text`, or "".
std::string line_with(const std::string& log, const std::string& text);
// `text` with `from` (which it must hold: a test failure else) replaced by `to`; `line`, when
// given, gets the 1-based line it was on.
std::string replaced(const std::string& text, const std::string& from, const std::string& to,
                     int* line = nullptr);

// Writes <dir>/gemkiosk.toml: headless kiosk of kWidth × kHeight drawing as fast as it can, a
// black background, one light, no attract mode, no inertia, no cross-fade, the
// given default catalogue, state under <dir>/state, snapshots in <dir>/snapshots. `extra` is
// appended (TOML).
std::filesystem::path write_config(const std::filesystem::path& dir,
                                   const std::filesystem::path& catalogue,
                                   const std::string& extra = "");

// The kiosk's command line for a replay of `recording` that ends when the view has settled,
// with a snapshot of the last frame.
std::vector<std::string> replay_command(const std::filesystem::path& config,
                                        const std::filesystem::path& recording);

// One touch contact's position at each SYN_REPORT, in the recording's own axis units.
struct RawTouch {
    glm::dvec2 first{0.0};
    glm::dvec2 last{0.0};
    std::vector<glm::dvec2> path;  // at every SYN_REPORT while down, first to last
    glm::dvec2 axis_max{0.0};      // from the recording's A: lines (ABS_X, ABS_Y)
};
// For recordings of one finger (protocol A or B): where it landed and where it lifted. The
// axes come from the recording's own description, or from `description` (a .desc file).
RawTouch one_finger_path(const std::filesystem::path& recording,
                         const std::filesystem::path& description = {});
// For a two-finger recording: the fingers' distance when both are first down and when both
// were last down.
glm::dvec2 two_finger_distances(const std::filesystem::path& recording);

// The catalogue's stone at `view`, as the kiosk configured by write_config draws it, linear RGB.
// `kind_tables`: its piece's kinds drawn from these tables (null: traced), as the kiosk draws
// them once it has built them.
Result<Image> reference_picture(
    const std::filesystem::path& catalogue, const kiosk::ViewState& view,
    const std::vector<std::shared_ptr<const Database>>& kind_tables = {});

// The one EGL context of this test process (contexts share Mesa's display: destroying one
// would tear down the others).
Result<bool> make_context_current();

// PSNR of the two images' 8-bit sRGB encodings, dB.
double psnr_srgb8(const Image& a, const Image& b);

// Expects `shown` to be catalogue `expected`'s stone at the start view (above 35 dB: the same
// renderer drew it) and clearly not `instead`'s (at least 5 dB further off); prints both, after
// `what`.
void expect_shows(const Image& shown, const std::filesystem::path& expected,
                  const std::filesystem::path& instead, const std::string& what,
                  const std::vector<std::shared_ptr<const Database>>& kind_tables = {});

}  // namespace gem::kiosk_e2e
