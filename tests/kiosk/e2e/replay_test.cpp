// The kiosk end to end, headless: gemkiosk replays a touchscreen recording as if the panel were
// plugged in, and its last frame must show the ring turned or zoomed exactly as the recording's
// own numbers say (read off its E: lines here), and not the other way. The comparison pictures
// come from the shading stage alone at the expected view and at the wrong ones.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "e2e_fixture.hpp"
#include "kiosk_process.hpp"
#include "stage/start_view.hpp"

namespace gem::kiosk_e2e {
namespace {

namespace fs = std::filesystem;
using kiosk::kStartView;
using kiosk::ViewState;

const fs::path kSharedEvemu = fs::path(GEM_TEST_DATA_DIR) / "evemu";
const fs::path kFixtures = fs::path(GEM_FIXTURES_DIR) / "kiosk";

// The view after one-finger drag steps of `steps_px` picture pixels each (x right, y down)
// from the start view, by the documented turntable rule (kiosk/gestures/turntable.hpp): the
// gain is kDegreesPerHeight per picture height; right lowers the azimuth, down raises the
// elevation; the elevation is held in the database's band (-10° .. 90° for gemtables'
// default) step by step, so motion past a limit is lost and motion back counts at once.
ViewState dragged_steps(const std::vector<glm::dvec2>& steps_px) {
    const double gain = kDegreesPerHeight / kHeight;
    ViewState v = kStartView;
    for (const glm::dvec2& step : steps_px) {
        v.azimuth_deg -= step.x * gain;
        v.elevation_deg = std::clamp(v.elevation_deg + step.y * gain, -10.0, 90.0);
    }
    return v;
}
ViewState dragged(glm::dvec2 drag_px) {
    return dragged_steps({drag_px});
}

glm::dvec2 to_picture(glm::dvec2 raw, const RawTouch& touch) {
    return raw / touch.axis_max * glm::dvec2(kWidth, kHeight);
}
glm::dvec2 picture_drag(const RawTouch& touch) {
    return to_picture(touch.last - touch.first, touch);
}
std::vector<glm::dvec2> picture_steps(const RawTouch& touch, double sign = 1.0) {
    std::vector<glm::dvec2> steps;
    for (std::size_t i = 1; i < touch.path.size(); ++i) {
        steps.push_back(sign * to_picture(touch.path[i] - touch.path[i - 1], touch));
    }
    return steps;
}

struct Replayed {
    Image last;
    std::string log;
};

// Runs the kiosk on `recording` against the sapphire catalogue; fails the test on error.
Replayed replay(const std::string& name, const fs::path& recording, fs::path* catalogue_out) {
    auto catalogue = test_catalogue("oval-sapphire");
    EXPECT_TRUE(catalogue.ok()) << (catalogue.ok() ? "" : catalogue.error());
    if (!catalogue) return {};
    *catalogue_out = catalogue.value();
    const fs::path dir = fresh_dir(name);
    const Finished run = run_kiosk(replay_command(write_config(dir, catalogue.value()), recording),
                                   std::chrono::seconds(180));
    EXPECT_EQ(run.status, 0) << run.log;
    auto last = read_png(dir / "snapshots" / "last.png");
    EXPECT_TRUE(last.ok()) << run.log;
    if (!last) return {};
    return {std::move(last).value(), run.log};
}

// The kiosk's last frame must match the expected view far better than the others.
void expect_view(const Image& shown, const fs::path& catalogue, const ViewState& expected,
                 const std::vector<std::pair<std::string, ViewState>>& wrong) {
    auto right = reference_picture(catalogue, expected);
    ASSERT_TRUE(right.ok()) << right.error();
    const double right_db = psnr_srgb8(shown, right.value());
    std::printf("expected view (az %.1f el %.1f zoom %.2f): %.1f dB\n", expected.azimuth_deg,
                expected.elevation_deg, expected.zoom, right_db);
    // Same renderer, same stored view, same level: only the kiosk's path to the view differs.
    EXPECT_GT(right_db, 35.0);
    for (const auto& [what, view] : wrong) {
        auto other = reference_picture(catalogue, view);
        ASSERT_TRUE(other.ok()) << other.error();
        const double db = psnr_srgb8(shown, other.value());
        std::printf("%s (az %.1f el %.1f zoom %.2f): %.1f dB\n", what.c_str(), view.azimuth_deg,
                    view.elevation_deg, view.zoom, db);
        EXPECT_LT(db, right_db - 5.0) << what;
    }
}

TEST(KioskReplay, DragRightTurnsTheRingWithTheFinger) {
    const fs::path recording = kFixtures / "atmel-drag-right.events";
    fs::path catalogue;
    const Replayed r = replay("drag-right", recording, &catalogue);
    ASSERT_FALSE(r.last.pixels.empty());
    const glm::dvec2 drag = picture_drag(one_finger_path(recording));
    ASSERT_GT(drag.x, 70.0);  // 300 of 799 panel units: 75 of 200 picture pixels
    ViewState backwards = kStartView;
    backwards.azimuth_deg += drag.x * kDegreesPerHeight / kHeight;
    expect_view(r.last, catalogue, dragged(drag),
                {{"turned the wrong way", backwards}, {"not turned", kStartView}});
}

TEST(KioskReplay, RealProtocolADiagonalDragTurnsAndTilts) {
    // N-Trig panel, multitouch protocol A (SYN_MT_REPORT), its description in a separate .desc.
    const fs::path recording = kSharedEvemu / "N-Trig_MultiTouch.1-finger-drag-NW-SE.events";
    fs::path catalogue;
    const Replayed r = replay("ntrig-diagonal", recording, &catalogue);
    ASSERT_FALSE(r.last.pixels.empty());
    const RawTouch touch = one_finger_path(recording, kSharedEvemu / "N-Trig_MultiTouch.desc");
    const glm::dvec2 drag = picture_drag(touch);
    ASSERT_GT(drag.x, 0.0);  // north-west to south-east: right and down
    ASSERT_GT(drag.y, 0.0);
    // The finger's path matters, not just its ends: it pushes the elevation into its limit.
    const ViewState expected = dragged_steps(picture_steps(touch));
    ViewState mirrored = dragged_steps(picture_steps(touch, -1.0));
    ViewState tilt_only = dragged({0.0, drag.y});
    expect_view(r.last, catalogue, expected,
                {{"turned and tilted the wrong way", mirrored},
                 {"tilted but not turned", tilt_only},
                 {"not moved", kStartView}});
}

TEST(KioskReplay, PinchOutZoomsIn) {
    const fs::path recording = kFixtures / "atmel-pinch-out.events";
    fs::path catalogue;
    const Replayed r = replay("pinch-out", recording, &catalogue);
    ASSERT_FALSE(r.last.pixels.empty());
    const glm::dvec2 distances = two_finger_distances(recording);
    const double ratio = distances.y / distances.x;  // 240 / 160
    ASSERT_NEAR(ratio, 1.5, 0.01);
    ViewState in = kStartView, out = kStartView;
    in.zoom = kStartView.zoom * ratio;
    out.zoom = kStartView.zoom / ratio;
    expect_view(r.last, catalogue, in, {{"zoomed out", out}, {"not zoomed", kStartView}});
}

TEST(KioskReplay, SynDroppedMidDragStillEndsWhereTheFingerLifted) {
    // The recording loses ten frames of the drag and the lift to SYN_DROPPED; after reading the
    // device's state back the kiosk must end exactly where the undamaged drag ends.
    const fs::path recording = kFixtures / "atmel-drag-right-syn-dropped.events";
    fs::path catalogue;
    const Replayed r = replay("drag-syn-dropped", recording, &catalogue);
    ASSERT_FALSE(r.last.pixels.empty());
    const glm::dvec2 drag = picture_drag(one_finger_path(kFixtures / "atmel-drag-right.events"));
    ViewState backwards = kStartView;
    backwards.azimuth_deg += drag.x * kDegreesPerHeight / kHeight;
    expect_view(r.last, catalogue, dragged(drag),
                {{"turned the wrong way", backwards}, {"not turned", kStartView}});
}

}  // namespace
}  // namespace gem::kiosk_e2e
