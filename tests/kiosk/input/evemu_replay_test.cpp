// EvemuReplay on the real recordings in tests/data/evemu and the SYN_DROPPED fixture. Every
// expected value comes from a trivial scan of the recording's own "E:" lines (raw_recording.hpp)
// or from the numbers written in the file. With the picture the size of the device's axis
// maxima and no rotation, a picture pixel equals the raw axis value (touch_mapping.hpp: p W).

#include "input/evemu_replay.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "raw_recording.hpp"

namespace gem::kiosk {
namespace {

const std::string data_dir = std::string(GEM_TEST_DATA_DIR) + "/evemu/";
const std::string atmel_drag = data_dir + "Atmel_maXTouch_Touchscreen.1-finger-drag-up-down.events";
const std::string atmel_two =
    data_dir + "Atmel_maXTouch_Touchscreen.2-fingers-touch-release.events";
const std::string ntrig_drag = data_dir + "N-Trig_MultiTouch.1-finger-drag-NW-SE.events";
const std::string tablet_drag =
    std::string(GEM_FIXTURES_DIR) + "/kiosk/qemu-usb-tablet-drag.events";
const std::string dropped_fixture =
    std::string(GEM_FIXTURES_DIR) +
    "/evemu/Atmel_maXTouch_Touchscreen.2-fingers-syn-dropped.events";

EvemuReplayOptions options_for(const std::string& events, const std::string& description = "") {
    EvemuReplayOptions options;
    options.events_path = events;
    options.description_path = description;
    return options;
}

struct RawContact {
    int id;
    double x;
    double y;
    bool operator<(const RawContact& other) const { return id < other.id; }
};
using RawFrames = std::vector<std::vector<RawContact>>;

// Protocol B as the kernel keeps it: per slot the last tracking id and position; a frame at
// each SYN_REPORT. SYN_DROPPED changes no state, so this is the device's true state.
RawFrames scan_protocol_b(const std::vector<test::RawEvent>& events) {
    std::map<int, RawContact> slots;  // slot -> contact (id -1: none)
    int slot = 0;
    RawFrames frames;
    for (const test::RawEvent& e : events) {
        if (e.type == EV_ABS && e.code == ABS_MT_SLOT) slot = e.value;
        if (slots.count(slot) == 0) slots[slot] = {-1, 0, 0};
        if (e.type == EV_ABS && e.code == ABS_MT_TRACKING_ID) slots[slot].id = e.value;
        if (e.type == EV_ABS && e.code == ABS_MT_POSITION_X) slots[slot].x = e.value;
        if (e.type == EV_ABS && e.code == ABS_MT_POSITION_Y) slots[slot].y = e.value;
        if (e.type == EV_SYN && e.code == SYN_REPORT) {
            std::vector<RawContact> frame;
            for (const auto& [index, contact] : slots) {
                if (contact.id >= 0) frame.push_back(contact);
            }
            std::sort(frame.begin(), frame.end());
            frames.push_back(frame);
        }
    }
    return frames;
}

// Protocol A: the last MT position before each SYN_MT_REPORT is one contact of the frame.
RawFrames scan_protocol_a(const std::vector<test::RawEvent>& events) {
    RawFrames frames;
    std::vector<RawContact> frame;
    RawContact contact{0, 0, 0};
    bool has_contact = false;
    for (const test::RawEvent& e : events) {
        if (e.type == EV_ABS && e.code == ABS_MT_POSITION_X)
            contact.x = e.value, has_contact = true;
        if (e.type == EV_ABS && e.code == ABS_MT_POSITION_Y)
            contact.y = e.value, has_contact = true;
        if (e.type == EV_SYN && e.code == SYN_MT_REPORT && has_contact) {
            contact.id = static_cast<int>(frame.size());
            frame.push_back(contact);
            has_contact = false;
        }
        if (e.type == EV_SYN && e.code == SYN_REPORT) {
            frames.push_back(frame);
            frame.clear();
        }
    }
    return frames;
}

std::vector<TouchFrame> touch_frames(const std::vector<InputEvent>& events) {
    std::vector<TouchFrame> frames;
    for (const InputEvent& event : events) {
        if (const auto* frame = std::get_if<TouchFrame>(&event)) frames.push_back(*frame);
    }
    return frames;
}

// Plays a whole recording at once on a picture of the given size.
std::vector<TouchFrame> play_all(const std::string& path, glm::dvec2 picture) {
    Result<EvemuReplay> replay = EvemuReplay::open(options_for(path));
    EXPECT_TRUE(replay.ok()) << (replay.ok() ? "" : replay.error());
    if (!replay.ok()) return {};
    replay.value().set_mapping(TouchMapping(identity_calibration, 0, picture));
    replay.value().start(0.0);
    std::vector<TouchFrame> frames = touch_frames(replay.value().poll(1e9));
    EXPECT_TRUE(replay.value().finished());
    return frames;
}

void expect_frames_equal(const std::vector<TouchFrame>& played, const RawFrames& raw) {
    ASSERT_EQ(played.size(), raw.size());
    for (std::size_t i = 0; i < raw.size(); ++i) {
        std::vector<Contact> contacts = played[i].contacts;
        std::sort(contacts.begin(), contacts.end(),
                  [](const Contact& a, const Contact& b) { return a.id < b.id; });
        ASSERT_EQ(contacts.size(), raw[i].size()) << "frame " << i;
        for (std::size_t c = 0; c < contacts.size(); ++c) {
            EXPECT_EQ(contacts[c].id, raw[i][c].id) << "frame " << i;
            EXPECT_NEAR(contacts[c].position.x, raw[i][c].x, 1e-9) << "frame " << i;
            EXPECT_NEAR(contacts[c].position.y, raw[i][c].y, 1e-9) << "frame " << i;
        }
    }
}

std::size_t frames_with_contact(const RawFrames& raw) {
    return static_cast<std::size_t>(
        std::count_if(raw.begin(), raw.end(), [](const auto& frame) { return !frame.empty(); }));
}

TEST(EvemuReplay, AtmelOneFingerDragUpDown) {
    // Description from the recording's own header: ABS_MT_POSITION_X 0..799, Y 0..479.
    const std::vector<TouchFrame> played = play_all(atmel_drag, {799, 479});
    const RawFrames raw = scan_protocol_b(test::read_raw_events(atmel_drag));
    expect_frames_equal(played, raw);

    const std::size_t with_contact = static_cast<std::size_t>(std::count_if(
        played.begin(), played.end(), [](const TouchFrame& f) { return !f.contacts.empty(); }));
    EXPECT_EQ(with_contact, frames_with_contact(raw));
    EXPECT_EQ(with_contact, raw.size() - 1);  // every frame but the last, the lift
    ASSERT_FALSE(played.empty());
    // Numbers written in the recording: the finger lands at (361, 379) with tracking id 6.
    ASSERT_EQ(played.front().contacts.size(), 1u);
    EXPECT_EQ(played.front().contacts[0].id, 6);
    EXPECT_DOUBLE_EQ(played.front().contacts[0].position.x, 361.0);
    EXPECT_DOUBLE_EQ(played.front().contacts[0].position.y, 379.0);
    EXPECT_TRUE(played.back().contacts.empty());
    // "Drag up, down": y (down the panel) first falls to a minimum, then rises again.
    std::size_t top = 0;
    for (std::size_t i = 0; i < with_contact; ++i) {
        if (played[i].contacts[0].position.y < played[top].contacts[0].position.y) top = i;
    }
    EXPECT_LT(played[top].contacts[0].position.y, played.front().contacts[0].position.y - 100);
    EXPECT_GT(played[with_contact - 1].contacts[0].position.y,
              played[top].contacts[0].position.y + 100);
}

// Single touch with BTN_LEFT as the finger: the position at each SYN_REPORT while the button is
// down, nothing while it is up.
RawFrames scan_absolute_pointer(const std::vector<test::RawEvent>& events) {
    RawFrames frames;
    RawContact contact{0, 0, 0};
    bool down = false;
    for (const test::RawEvent& e : events) {
        if (e.type == EV_ABS && e.code == ABS_X) contact.x = e.value;
        if (e.type == EV_ABS && e.code == ABS_Y) contact.y = e.value;
        if (e.type == EV_KEY && e.code == BTN_LEFT) down = e.value != 0;
        if (e.type == EV_SYN && e.code == SYN_REPORT) {
            frames.push_back(down ? std::vector<RawContact>{contact} : std::vector<RawContact>{});
        }
    }
    return frames;
}

TEST(EvemuReplay, QemuTabletDragIsOneFinger) {
    // Recorded from the guest kernel's evdev device in the VM test; the description in the
    // recording's header says ABS_X and ABS_Y 0..32767, BTN_LEFT, no BTN_TOUCH.
    Result<EvemuReplay> replay = EvemuReplay::open(options_for(tablet_drag));
    ASSERT_TRUE(replay.ok()) << replay.error();
    EXPECT_EQ(replay.value().kind(), DeviceKind::absolute_pointer);
    const std::vector<TouchFrame> played = play_all(tablet_drag, {32767, 32767});
    const RawFrames raw = scan_absolute_pointer(test::read_raw_events(tablet_drag));
    expect_frames_equal(played, raw);
    // Numbers written in the recording: a hover at (11468, 16384), pressed there, moved right
    // in ten steps to 21299, released; the hover and the release are frames without a finger.
    ASSERT_EQ(played.size(), 13u);
    EXPECT_TRUE(played.front().contacts.empty());
    ASSERT_EQ(played[1].contacts.size(), 1u);
    EXPECT_DOUBLE_EQ(played[1].contacts[0].position.x, 11468.0);
    EXPECT_DOUBLE_EQ(played[1].contacts[0].position.y, 16384.0);
    ASSERT_EQ(played[11].contacts.size(), 1u);
    EXPECT_DOUBLE_EQ(played[11].contacts[0].position.x, 21299.0);
    EXPECT_TRUE(played.back().contacts.empty());
}

TEST(EvemuReplay, NTrigDiagonalDragProtocolA) {
    // The description is in N-Trig_MultiTouch.desc beside the recording (found by name):
    // ABS_MT_POSITION_X 0..9600, Y 0..7200.
    const std::vector<TouchFrame> played = play_all(ntrig_drag, {9600, 7200});
    const RawFrames raw = scan_protocol_a(test::read_raw_events(ntrig_drag));
    expect_frames_equal(played, raw);
    ASSERT_GE(raw.size(), 2u);
    EXPECT_EQ(frames_with_contact(raw), raw.size() - 1);
    EXPECT_TRUE(played.back().contacts.empty());
    // North-west to south-east: x and y both grow from the first frame to the last touched.
    const glm::dvec2 first = played.front().contacts.at(0).position;
    const glm::dvec2 last = played[played.size() - 2].contacts.at(0).position;
    EXPECT_DOUBLE_EQ(first.x, raw.front()[0].x);
    EXPECT_DOUBLE_EQ(last.y, raw[raw.size() - 2][0].y);
    EXPECT_GT(last.x - first.x, 0.5 * 9600);
    EXPECT_GT(last.y - first.y, 0.5 * 7200);
}

TEST(EvemuReplay, AtmelTwoFingersTouchAndRelease) {
    const std::vector<TouchFrame> played = play_all(atmel_two, {799, 479});
    const RawFrames raw = scan_protocol_b(test::read_raw_events(atmel_two));
    expect_frames_equal(played, raw);
    // The count of fingers goes 0 -> 1 -> 2 -> 1 -> 0 as the slots say.
    std::vector<std::size_t> counts{0};
    for (const TouchFrame& frame : played) {
        if (frame.contacts.size() != counts.back()) counts.push_back(frame.contacts.size());
    }
    EXPECT_EQ(counts, (std::vector<std::size_t>{0, 1, 2, 1, 0}));
}

TEST(EvemuReplay, SynDroppedResynchronisesToTheTrueState) {
    const std::vector<test::RawEvent> events = test::read_raw_events(dropped_fixture);
    const std::vector<TouchFrame> played = play_all(dropped_fixture, {799, 479});
    // The true state at every SYN_REPORT, dropped events applied, from the raw lines.
    expect_frames_equal(played, scan_protocol_b(events));

    // And as read off the fixture by hand (tests/fixtures/evemu/README.md).
    std::vector<std::size_t> after_drop;  // index of the frame that ends each drop
    std::size_t frame = 0;
    bool in_drop = false;
    for (const test::RawEvent& e : events) {
        if (e.type == EV_SYN && e.code == SYN_DROPPED) in_drop = true;
        if (e.type == EV_SYN && e.code == SYN_REPORT) {
            if (in_drop) after_drop.push_back(frame);
            in_drop = false;
            ++frame;
        }
    }
    ASSERT_EQ(after_drop.size(), 2u);
    // First drop: finger 8 landed and finger 7 moved while events were lost.
    const std::vector<Contact>& first = played.at(after_drop[0]).contacts;
    ASSERT_EQ(first.size(), 2u);
    EXPECT_EQ(first[0].id, 7);
    EXPECT_EQ(first[0].position, glm::dvec2(535, 177));
    EXPECT_EQ(first[1].id, 8);
    EXPECT_EQ(first[1].position, glm::dvec2(222, 306));
    // Second drop: finger 8 lifted during it, finger 7 moved.
    const std::vector<Contact>& second = played.at(after_drop[1]).contacts;
    ASSERT_EQ(second.size(), 1u);
    EXPECT_EQ(second[0].id, 7);
    EXPECT_EQ(second[0].position, glm::dvec2(538, 176));
}

TEST(EvemuReplay, RetimedToTheKioskClockWithTimeScale) {
    const std::vector<test::RawEvent> raw = test::read_raw_events(atmel_drag);
    EvemuReplayOptions options = options_for(atmel_drag);
    options.time_scale = 2.0;
    Result<EvemuReplay> opened = EvemuReplay::open(options);
    ASSERT_TRUE(opened.ok()) << opened.error();
    EvemuReplay& replay = opened.value();
    EXPECT_EQ(replay.event_count(), raw.size());
    EXPECT_EQ(replay.next_due_s(), std::numeric_limits<double>::infinity());  // not started
    replay.start(100.0);
    EXPECT_DOUBLE_EQ(replay.next_due_s(), 100.0);
    EXPECT_TRUE(replay.poll(99.0).empty());
    // Every event of the first frame has the first time stamp: exactly one frame now.
    std::vector<TouchFrame> frames = touch_frames(replay.poll(100.0));
    ASSERT_EQ(frames.size(), 1u);
    EXPECT_NEAR(frames[0].time_s, 100.0, 1e-6);
    // The second frame is due (t1 - t0) * 2 later.
    double second_raw = 0.0;
    for (std::size_t i = 1; i < raw.size(); ++i) {
        if (raw[i].time_s != raw[0].time_s) {
            second_raw = raw[i].time_s;
            break;
        }
    }
    EXPECT_NEAR(replay.next_due_s(), 100.0 + (second_raw - raw[0].time_s) * 2.0, 1e-9);
    frames = touch_frames(replay.poll(1e9));
    EXPECT_NEAR(frames.back().time_s, 100.0 + (raw.back().time_s - raw[0].time_s) * 2.0, 2e-6);
    EXPECT_TRUE(replay.finished());
    EXPECT_EQ(replay.next_due_s(), std::numeric_limits<double>::infinity());
}

TEST(EvemuReplay, LoopsForSoakRuns) {
    const std::vector<test::RawEvent> raw = test::read_raw_events(atmel_two);
    const double length = raw.back().time_s - raw.front().time_s;
    EvemuReplayOptions options = options_for(atmel_two);
    options.loop = true;
    options.loop_gap_s = 0.5;
    Result<EvemuReplay> opened = EvemuReplay::open(options);
    ASSERT_TRUE(opened.ok()) << opened.error();
    EvemuReplay& replay = opened.value();
    replay.start(10.0);
    const std::size_t one_pass = scan_protocol_b(raw).size();
    // Up to just before the third pass starts: two full passes, each its own frames.
    const double pass = length + 0.5;
    const std::vector<TouchFrame> frames = touch_frames(replay.poll(10.0 + 2 * pass - 1e-3));
    EXPECT_EQ(frames.size(), 2 * one_pass);
    EXPECT_FALSE(replay.finished());
    EXPECT_NEAR(replay.next_due_s(), 10.0 + 2 * pass, 1e-9);
    // The second pass starts like the first.
    EXPECT_EQ(frames[one_pass].contacts.size(), frames[0].contacts.size());
    EXPECT_EQ(frames[one_pass].contacts.at(0).position, frames[0].contacts.at(0).position);
}

// Writes a small file for the error tests.
std::string write_file(const std::string& name, const std::string& text) {
    const std::filesystem::path dir = std::filesystem::path(GEM_ARTIFACT_DIR) / "evemu";
    std::filesystem::create_directories(dir);
    const std::filesystem::path path = dir / name;
    std::ofstream(path) << text;
    return path.string();
}

TEST(EvemuReplay, ErrorsNameTheFileAndLine) {
    const Result<EvemuReplay> missing = EvemuReplay::open(options_for("/nonexistent/x.events"));
    ASSERT_FALSE(missing.ok());
    EXPECT_NE(missing.error().find("/nonexistent/x.events"), std::string::npos);
    EXPECT_NE(missing.error().find("No such file"), std::string::npos);

    const std::string damaged = write_file(
        "damaged.events", "E: 0.000001 0003 0035 0100\nE: 0.000001 0000 0000 0000\nE: 0.01 zz\n");
    const Result<EvemuReplay> bad =
        EvemuReplay::open(options_for(damaged, data_dir + "N-Trig_MultiTouch.desc"));
    ASSERT_FALSE(bad.ok());
    EXPECT_NE(bad.error().find(damaged + ":3:"), std::string::npos) << bad.error();

    const std::string no_description = write_file("lonely.events", "E: 0.000001 0000 0000 0000\n");
    const Result<EvemuReplay> lonely = EvemuReplay::open(options_for(no_description));
    ASSERT_FALSE(lonely.ok());
    EXPECT_NE(lonely.error().find(no_description), std::string::npos);
    EXPECT_NE(lonely.error().find("description"), std::string::npos);
}

// An event line whose fields are wider than libevemu's format reads (a five-digit code) is
// refused by the kiosk, naming its line, before libevemu's reader, which leaks on it.
TEST(EvemuReplay, AnEventLineWiderThanLibevemuReadsIsRefusedWithItsLine) {
    const std::string wide =
        write_file("wide.events", "E: 0.000001 0003 0035 0100\nE: 0.075000 0000 0000A 0\n");
    const Result<EvemuReplay> opened =
        EvemuReplay::open(options_for(wide, data_dir + "N-Trig_MultiTouch.desc"));
    ASSERT_FALSE(opened.ok());
    EXPECT_EQ(opened.error(),
              "evemu recording " + wide + ":2: damaged event line \"E: 0.075000 0000 0000A 0\"");
}

// A description with no line libevemu would read (empty, blank lines, one character, a NUL) is
// refused before libevemu sees it: its reader returns from that case without freeing its line
// buffer, which the sanitizer pass reports as a leak (found by fuzz_config).
TEST(EvemuReplay, AnEmptyDescriptionIsRefusedWithoutLeaking) {
    const std::string events = write_file("one.events", "E: 0.000001 0000 0000 0000\n");
    int n = 0;
    for (const std::string& text :
         {std::string(""), std::string("\n\n\n"), std::string("x"), std::string("\0N: x\n", 7)}) {
        const std::string desc = write_file("empty-" + std::to_string(n++) + ".desc", text);
        const Result<EvemuReplay> opened = EvemuReplay::open(options_for(events, desc));
        ASSERT_FALSE(opened.ok());
        EXPECT_EQ(opened.error(),
                  "evemu description " + desc + ": not a valid evemu device description");
    }
}

}  // namespace
}  // namespace gem::kiosk
