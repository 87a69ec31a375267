#include "input/evemu_replay.hpp"

#include <evemu.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <string_view>

#include "import/import_text.hpp"

namespace gem::kiosk {

namespace {

struct FileCloser {
    void operator()(std::FILE* file) const { std::fclose(file); }
};
using File = std::unique_ptr<std::FILE, FileCloser>;
struct EvemuDeleter {
    void operator()(evemu_device* device) const { evemu_delete(device); }
};
using EvemuDevice = std::unique_ptr<evemu_device, EvemuDeleter>;

bool is_description_line(const std::string& line) {
    static constexpr const char* prefixes[] = {"N:", "I:", "P:", "B:", "A:", "L:", "S:"};
    for (const char* prefix : prefixes) {
        if (line.rfind(prefix, 0) == 0) return true;
    }
    return false;
}

bool is_blank_or_comment(const std::string& line) {
    const std::size_t first = line.find_first_not_of(" \t\r");
    return first == std::string::npos || line[first] == '#';
}

// "A.b.c.events" -> the first of A.b.c.desc, A.b.desc, A.desc that exists.
std::string find_description_beside(const std::filesystem::path& events_path) {
    std::string stem = events_path.stem().string();
    for (;;) {
        const std::filesystem::path candidate = events_path.parent_path() / (stem + ".desc");
        if (std::filesystem::exists(candidate)) return candidate.string();
        const std::size_t dot = stem.rfind('.');
        if (dot == std::string::npos || dot == 0) return {};
        stem.resize(dot);
    }
}

// Whether libevemu's reader would find a first line: it skips lines of at most one character
// (strlen, so up to a NUL) and, when there is none, returns without freeing its line buffer
// (evemu_read in libevemu 2.7, "This appears to be an empty file"; found by fuzz_config).
bool has_a_first_line(std::string_view text) {
    if (text.find('\0') != std::string_view::npos) return false;  // a description is text
    for (std::size_t start = 0; start < text.size();) {
        const std::size_t end = std::min(text.find('\n', start), text.size());
        const std::size_t with_newline = end - start + (end < text.size() ? 1 : 0);
        if (with_newline > 1) return true;
        start = end + 1;
    }
    return false;
}

Result<EvemuDevice> read_description(const std::string& path) {
    auto text = import::read_whole_file(path);
    if (!text) return Error{"evemu description " + text.error()};
    const std::string invalid =
        "evemu description " + path + ": not a valid evemu device description";
    if (!has_a_first_line(text.value())) return Error{invalid};
    File file(fmemopen(text.value().data(), text.value().size(), "r"));
    EvemuDevice device(evemu_new(nullptr));
    if (!file || !device || evemu_read(device.get(), file.get()) <= 0) return Error{invalid};
    return device;
}

DeviceCapabilities capabilities_of(const evemu_device* d) {
    const auto has_abs = [d](int code) { return evemu_has_event(d, EV_ABS, code) != 0; };
    const auto range = [d](int code) {
        return AxisRange{evemu_get_abs_minimum(d, code), evemu_get_abs_maximum(d, code)};
    };
    DeviceCapabilities c;
    c.direct = evemu_has_prop(d, INPUT_PROP_DIRECT) != 0;
    c.mt_position = has_abs(ABS_MT_POSITION_X) && has_abs(ABS_MT_POSITION_Y);
    c.mt_slot = has_abs(ABS_MT_SLOT);
    c.abs_xy = has_abs(ABS_X) && has_abs(ABS_Y);
    c.btn_touch = evemu_has_event(d, EV_KEY, BTN_TOUCH) != 0;
    c.rel_xy = evemu_has_event(d, EV_REL, REL_X) && evemu_has_event(d, EV_REL, REL_Y);
    c.btn_left = evemu_has_event(d, EV_KEY, BTN_LEFT) != 0;
    c.typing_keys = evemu_has_event(d, EV_KEY, KEY_A) && evemu_has_event(d, EV_KEY, KEY_ENTER);
    c.mt_x = range(ABS_MT_POSITION_X);
    c.mt_y = range(ABS_MT_POSITION_Y);
    c.abs_x = range(ABS_X);
    c.abs_y = range(ABS_Y);
    c.slot_maximum = range(ABS_MT_SLOT).maximum;
    return c;
}

// One "E:" line through libevemu's own parser. A line libevemu would refuse is refused here
// first, by its own format with its field widths (evemu_read_event in libevemu 2.7): it leaks
// its line buffer on that path and prints to stderr (a five-digit code, found by fuzz_config).
bool parse_event_line(std::string line, input_event& event) {
    unsigned long seconds = 0;
    unsigned int microseconds = 0, type = 0, code = 0;
    int value = 0;
    if (std::sscanf(line.c_str(), "E: %lu.%06u %04x %04x %d\n", &seconds, &microseconds, &type,
                    &code, &value) != 5)
        return false;
    line.push_back('\n');
    File file(fmemopen(line.data(), line.size(), "r"));
    return file && evemu_read_event(file.get(), &event) == 1;
}

}  // namespace

Result<EvemuReplay> EvemuReplay::open(const EvemuReplayOptions& options) {
    const std::string& path = options.events_path;
    std::ifstream stream(path);
    if (!stream) return Error{"evemu recording " + path + ": " + std::strerror(errno)};
    if (!(options.time_scale > 0.0) || !std::isfinite(options.time_scale))
        return Error{"evemu recording " + path + ": time scale must be positive"};

    std::vector<input_event> events;
    bool has_header = false;
    std::string line;
    for (int number = 1; std::getline(stream, line); ++number) {
        if (is_blank_or_comment(line)) continue;
        if (line.rfind("E:", 0) == 0) {
            input_event event{};
            if (!parse_event_line(line, event)) {
                return Error{"evemu recording " + path + ":" + std::to_string(number) +
                             ": damaged event line \"" + line + "\""};
            }
            events.push_back(event);
        } else if (events.empty() && is_description_line(line)) {
            has_header = true;
        } else {
            return Error{"evemu recording " + path + ":" + std::to_string(number) +
                         ": not an evemu line \"" + line + "\""};
        }
    }
    if (events.empty()) return Error{"evemu recording " + path + ": no events"};

    std::string description_path = options.description_path;
    if (description_path.empty() && has_header) description_path = path;
    if (description_path.empty()) description_path = find_description_beside(path);
    if (description_path.empty()) {
        return Error{"evemu recording " + path +
                     ": no device description in it and no .desc file beside it"};
    }
    Result<EvemuDevice> description = read_description(description_path);
    if (!description) return Error{description.error()};
    const DeviceCapabilities capabilities = capabilities_of(description.value().get());
    const DeviceKind kind = classify(capabilities);
    if (kind != DeviceKind::touchscreen && kind != DeviceKind::absolute_pointer &&
        kind != DeviceKind::pointer) {
        return Error{"evemu recording " + path + ": device \"" +
                     evemu_get_name(description.value().get()) +
                     "\" is neither a touchscreen nor a pointer"};
    }
    return EvemuReplay(options, evemu_get_name(description.value().get()), kind,
                       touch_axes(capabilities), std::move(events));
}

EvemuReplay::EvemuReplay(EvemuReplayOptions options, std::string device_name, DeviceKind kind,
                         const TouchAxes& axes, std::vector<input_event> events)
    : options_(std::move(options)),
      device_name_(std::move(device_name)),
      kind_(kind),
      axes_(axes),
      events_(std::move(events)),
      decoder_(kind, axes) {
    recorded_origin_s_ = event_time_s(events_.front());
    state_.slots.resize(static_cast<std::size_t>(axes_.slot_count));
}

void EvemuReplay::start(double now_s) {
    started_ = true;
    next_ = 0;
    start_s_ = now_s;
    decoder_ = DeviceDecoder(kind_, axes_);
    state_ = TouchSnapshot{};
    state_.slots.resize(static_cast<std::size_t>(axes_.slot_count));
}

double EvemuReplay::due_s(std::size_t index) const {
    return start_s_ + (event_time_s(events_[index]) - recorded_origin_s_) * options_.time_scale;
}

double EvemuReplay::next_due_s() const {
    if (!started_ || finished()) return std::numeric_limits<double>::infinity();
    return due_s(next_);
}

bool EvemuReplay::finished() const {
    return started_ && next_ >= events_.size();
}

void EvemuReplay::restart_loop() {
    const double pass_s =
        event_time_s(events_.back()) - recorded_origin_s_ + std::max(options_.loop_gap_s, 1e-3);
    start(start_s_ + pass_s * options_.time_scale);
}

std::vector<InputEvent> EvemuReplay::poll(double now_s) {
    std::vector<InputEvent> out;
    const auto state = [this] { return state_; };
    while (started_ && next_ < events_.size() && due_s(next_) <= now_s) {
        input_event event = events_[next_];
        const double kiosk_s = due_s(next_);
        const double seconds = std::floor(kiosk_s);
        event.input_event_sec = static_cast<decltype(event.input_event_sec)>(seconds);
        event.input_event_usec =
            static_cast<decltype(event.input_event_usec)>(std::lround((kiosk_s - seconds) * 1e6));
        apply_to_state(event);
        decoder_.feed(event, mapping_, state, out);
        ++next_;
        if (next_ == events_.size() && options_.loop) restart_loop();
    }
    return out;
}

void EvemuReplay::apply_to_state(const input_event& event) {
    if (event.type == EV_KEY) {
        if (event.code == BTN_TOUCH) state_.touching = event.value != 0;
        if (event.code == BTN_LEFT) state_.left_button = event.value != 0;
        return;
    }
    if (event.type != EV_ABS) return;
    switch (event.code) {
        case ABS_X:
            state_.x = event.value;
            return;
        case ABS_Y:
            state_.y = event.value;
            return;
        case ABS_MT_SLOT:
            state_.current_slot = event.value;
            return;
        default:
            break;
    }
    const int slot = state_.current_slot;
    if (axes_.protocol != TouchProtocol::multitouch_b || slot < 0 || slot >= axes_.slot_count)
        return;
    TouchSlotState& s = state_.slots[static_cast<std::size_t>(slot)];
    if (event.code == ABS_MT_TRACKING_ID) s.tracking_id = event.value;
    if (event.code == ABS_MT_POSITION_X) s.x = event.value;
    if (event.code == ABS_MT_POSITION_Y) s.y = event.value;
}

}  // namespace gem::kiosk
