#include "e2e_fixture.hpp"

#include <unistd.h>

#include <GLES3/gl3.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <map>
#include <memory>
#include <sstream>

#include "catalogue/validate.hpp"
#include "gpu/egl_context.hpp"
#include "gpu/frame_composer.hpp"
#include "gpu/hdr_picture.hpp"
#include "gpu/render_target.hpp"
#include "kiosk_process.hpp"
#include "picture/camera.hpp"
#include "settings/kiosk_config.hpp"
#include "stage/picture_choice.hpp"
#include "stage/scene_selection.hpp"
#include "stage/start_view.hpp"
#include "stage/stone_scene.hpp"

namespace gem::kiosk_e2e {

namespace fs = std::filesystem;

fs::path fresh_dir(const std::string& name) {
    const fs::path dir = fs::path(GEM_ARTIFACT_DIR) / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

Result<fs::path> test_catalogue(const std::string& stone) {
    const fs::path dir = fs::path(GEM_ARTIFACT_DIR) / "catalogues" / stone;
    const fs::path database = dir / (stone + ".gemdb");
    fs::create_directories(dir);
    if (!fs::exists(database)) {
        // gemtables writes beside and renames, so tests running at once never see half a file.
        const Finished built =
            run_kiosk({GEMTABLES_PATH, "build",
                       std::string(GEM_SOURCE_DIR) + "/config/stones/" + stone + ".toml", "-o",
                       database.string(), "--levels", "64,128", "--spacing", "10", "--depth", "6"},
                      std::chrono::seconds(300));
        if (built.status != 0) return Error{"gemtables build failed:\n" + built.log};
    }
    std::ofstream manifest(dir / "catalogue.toml");
    manifest << "[catalogue]\nname = \"" << stone << "\"\n\n[[stone]]\nname = \"" << stone
             << "\"\ndatabase = \"" << stone << ".gemdb\"\nring = \"parametric\"\n";
    return dir;
}

std::string read_text(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void write_text(const fs::path& file, const std::string& text) {
    std::ofstream(file, std::ios::binary | std::ios::trunc) << text;
}

std::string line_with(const std::string& log, const std::string& text) {
    const auto at = log.find(text);
    if (at == std::string::npos) return "";
    const auto start = log.rfind('\n', at) + 1;
    return log.substr(start, log.find('\n', at) - start);
}

std::string replaced(const std::string& text, const std::string& from, const std::string& to,
                     int* line) {
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at == std::string::npos) return text;
    if (line != nullptr) {
        *line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + at, '\n'));
    }
    return text.substr(0, at) + to + text.substr(at + from.size());
}

fs::path write_config(const fs::path& dir, const fs::path& catalogue, const std::string& extra) {
    const fs::path file = dir / "gemkiosk.toml";
    std::ofstream out(file);
    out << "crossfade_s = 0.0\n"
        << "[display]\nbackend = \"headless\"\nheadless_width = " << kWidth
        << "\nheadless_height = " << kHeight << "\nheadless_rate_hz = 0.0\n"
        << "[input]\ndevice_dir = \"" << (dir / "no-input").string() << "\"\n"
        << "[gestures]\ndegrees_per_picture_height = " << kDegreesPerHeight
        << "\ninertia_half_life_s = 0.0\ntap = \"none\"\ntwo_finger_tap = \"none\"\n"
        << "[attract]\nidle_s = 0.0\n"
        << "[render]\nmethod = \"table\"\ncube_face = 64\ndepth = 6\n"
        // A still view by its count of frames, not by time: what it shows once settled is the
        // same on a loaded machine (reference_picture() draws those frames).
        << "[picture]\nstill_frames = 16\nstill_seconds = 0.0\n"
        << "[catalogue]\ndefault_dir = \"" << catalogue.string() << "\"\nstate_dir = \""
        << (dir / "state").string() << "\"\ninbox_dir = \"" << (dir / "state" / "inbox").string()
        << "\"\nsettle_s = 0.3\n"
        << "[snapshot]\ndir = \"" << (dir / "snapshots").string() << "\"\n"
        << "[[background]]\nname = \"black\"\nkind = \"colour\"\ncolour = [0.0, 0.0, 0.0]\n"
        << "[[lighting]]\nname = \"one light\"\nenvironment_intensity = 1.0\n"
        << "[[lighting.light]]\nposition = [-30.0, 80.0, 45.0]\ncolour = [2.0, 2.0, 2.0]\n"
        << extra;
    return file;
}

std::vector<std::string> replay_command(const fs::path& config, const fs::path& recording) {
    return {GEMKIOSK_PATH,     "--config",         config.string(),
            "--replay",        recording.string(), "--exit-after-replay",
            "--snapshot-last", "--seconds",        "120"};
}

namespace {

struct RawEvent {
    int type = 0;
    int code = 0;
    int value = 0;
};

// The E: lines and the ABS_X/ABS_Y maxima of the A: lines (evemu's format: type and code in
// hex, value decimal; "A: <code hex> <min> <max> ...").
std::vector<RawEvent> read_events(const fs::path& recording, glm::dvec2* axis_max) {
    std::ifstream in(recording);
    std::vector<RawEvent> events;
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream words(line);
        std::string tag;
        words >> tag;
        if (tag == "E:") {
            std::string time, type, code;
            int value = 0;
            words >> time >> type >> code >> value;
            events.push_back({std::stoi(type, nullptr, 16), std::stoi(code, nullptr, 16), value});
        } else if (tag == "A:" && axis_max != nullptr) {
            std::string code;
            int min = 0, max = 0;
            words >> code >> min >> max;
            if (code == "00") axis_max->x = max;
            if (code == "01") axis_max->y = max;
        }
    }
    return events;
}

constexpr int kEvSyn = 0, kEvAbs = 3, kSynReport = 0, kSynMtReport = 2;
constexpr int kAbsX = 0x00, kAbsY = 0x01, kMtSlot = 0x2f, kMtX = 0x35, kMtY = 0x36,
              kMtTrackingId = 0x39;

}  // namespace

RawTouch one_finger_path(const fs::path& recording, const fs::path& description) {
    RawTouch touch;
    if (!description.empty()) read_events(description, &touch.axis_max);
    glm::dvec2 position(0.0);
    bool down = false, seen = false;
    for (const RawEvent& e : read_events(recording, &touch.axis_max)) {
        if (e.type == kEvAbs && (e.code == kMtX || e.code == kAbsX)) position.x = e.value;
        if (e.type == kEvAbs && (e.code == kMtY || e.code == kAbsY)) position.y = e.value;
        if (e.type == kEvAbs && e.code == kMtTrackingId) down = e.value >= 0;
        if (e.type == kEvSyn && e.code == kSynMtReport) down = true;  // protocol A: a contact
        if (e.type == kEvSyn && e.code == kSynReport && down) {
            if (!seen) touch.first = position;
            seen = true;
            touch.last = position;
            touch.path.push_back(position);
        }
    }
    return touch;
}

glm::dvec2 two_finger_distances(const fs::path& recording) {
    std::map<int, glm::dvec2> slots;
    std::map<int, bool> active;
    int slot = 0;
    double first = -1.0, last = -1.0;
    for (const RawEvent& e : read_events(recording, nullptr)) {
        if (e.type == kEvAbs && e.code == kMtSlot) slot = e.value;
        if (e.type == kEvAbs && e.code == kMtTrackingId) active[slot] = e.value >= 0;
        if (e.type == kEvAbs && e.code == kMtX) slots[slot].x = e.value;
        if (e.type == kEvAbs && e.code == kMtY) slots[slot].y = e.value;
        if (e.type == kEvSyn && e.code == kSynReport && active[0] && active[1]) {
            const double d = glm::length(slots[0] - slots[1]);
            if (first < 0.0) first = d;
            last = d;
        }
    }
    return {first, last};
}

Result<bool> make_context_current() {
    static std::unique_ptr<gpu::EglContext> context;
    if (!context) {
        auto made = gpu::EglContext::headless();
        if (!made) return Error{made.error()};
        context = std::make_unique<gpu::EglContext>(std::move(made).value());
    }
    return true;
}

Result<Image> reference_picture(const fs::path& catalogue, const kiosk::ViewState& view,
                                const std::vector<std::shared_ptr<const Database>>& kind_tables) {
    auto context = make_context_current();
    if (!context) return Error{context.error()};
    auto validated = kiosk::validate_catalogue(catalogue);
    if (!validated) return Error{validated.error()};
    // The same presets the kiosk reads from write_config's file, parsed the same way.
    // Per process: tests running at once each draw their own references.
    const fs::path config_dir = fresh_dir("reference-config-" + std::to_string(::getpid()));
    const kiosk::ConfigLoad config = kiosk::load_config(write_config(config_dir, catalogue));
    if (!config.errors.empty()) return Error{"test config: " + config.errors.front()};
    kiosk::SceneSelection selection(config.config.backgrounds, config.config.lightings);
    selection.set_catalogue(validated.value());
    kiosk::RenderChoice render;
    render.cube_face = config.config.render.cube_face;
    render.depth = config.config.render.depth;
    render.wait_for_views = true;
    render.stone_share = config.config.picture.stone_share;
    auto scene = kiosk::StoneScene::make(selection.stone(), selection.look(), render, kind_tables);
    if (!scene) return Error{scene.error()};
    // A piece's small stones get their models as the kiosk gives them when it makes a scene.
    auto models = scene.value()->choose_stone_models({kWidth, kHeight});
    if (!models) return Error{models.error()};
    auto target = gpu::RenderTarget::make(kWidth, kHeight);
    if (!target) return Error{target.error()};
    // The picture's finishing passes, as the kiosk's config sets them, and the frames a still
    // view is averaged over once the kiosk's view has come to rest.
    gpu::PictureOptions options = kiosk::picture_options(config.config.picture);
    options.display = kiosk::display_transform(config.config.picture, selection.look());
    auto scene_picture = gpu::HdrPicture::make(kWidth, kHeight, options);
    if (!scene_picture) return Error{scene_picture.error()};
    gpu::HdrPicture& picture = scene_picture.value();
    for (int frame = 0; frame < options.still_frames; ++frame) {
        picture.begin_frame(true);
        // The kiosk's own frame (gpu/frame_composer.hpp), still: no turn to prepare for.
        auto drawn = gpu::compose_frame({.renderer = &scene.value()->renderer(),
                                         .view = scene.value()->frame_view(view, {kWidth, kHeight}),
                                         .wait = gpu::FrameWait::frame,
                                         .picture = &picture},
                                        target.value());
        if (!drawn) return Error{drawn.error()};
        if (auto shown = drawn.value().scene(); !shown) return Error{shown.error()};
    }
    return target.value().read();
}

double psnr_srgb8(const Image& a, const Image& b) {
    const std::vector<std::uint8_t> x = to_srgb8(a, 3);
    const std::vector<std::uint8_t> y = to_srgb8(b, 3);
    if (x.size() != y.size() || x.empty()) return 0.0;
    double sum = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
        const double d = static_cast<double>(x[i]) - static_cast<double>(y[i]);
        sum += d * d;
    }
    const double mse = sum / static_cast<double>(x.size());
    return mse == 0.0 ? 99.0 : 10.0 * std::log10(255.0 * 255.0 / mse);
}

void expect_shows(const Image& shown, const fs::path& expected, const fs::path& instead,
                  const std::string& what,
                  const std::vector<std::shared_ptr<const Database>>& kind_tables) {
    auto right = reference_picture(expected, kiosk::kStartView, kind_tables);
    ASSERT_TRUE(right.ok()) << right.error();
    auto wrong = reference_picture(instead, kiosk::kStartView);
    ASSERT_TRUE(wrong.ok()) << wrong.error();
    const double right_db = psnr_srgb8(shown, right.value());
    const double wrong_db = psnr_srgb8(shown, wrong.value());
    std::printf("%s: %.1f dB to %s, %.1f dB to %s\n", what.c_str(), right_db,
                expected.filename().c_str(), wrong_db, instead.filename().c_str());
    EXPECT_GT(right_db, 35.0);
    EXPECT_LT(wrong_db, right_db - 5.0);
}

}  // namespace gem::kiosk_e2e
