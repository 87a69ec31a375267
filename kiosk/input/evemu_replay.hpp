#pragma once
// Plays an evemu recording (the text format of evemu-record: a device description, "N:", "I:",
// "P:", "B:", "A:" lines, and events, "E: <sec>.<usec> <type> <code> <value>") as if the device
// were plugged in: events go through the same DeviceDecoder and TouchMapping as a real device,
// re-timed to the kiosk's clock. The description comes from the .events file's own header when
// it has one, else from a .desc file: given, or found beside the recording by dropping
// ".<part>" suffixes from its name ("N-Trig_MultiTouch.1-finger-drag-NW-SE.events" ->
// "N-Trig_MultiTouch.desc").
//
// SYN_DROPPED in a recording means what it means from the kernel: the decoder discards up to
// the next SYN_REPORT and then asks for the device's state, which the replay keeps as the kernel
// would, by applying every recorded event, the discarded ones included.

#include <cstddef>
#include <string>
#include <vector>

#include <linux/input.h>

#include "input/device_decoder.hpp"
#include "input/device_kind.hpp"
#include "input/input_event.hpp"
#include "input/touch_mapping.hpp"
#include "util/result.hpp"

namespace gem::kiosk {

struct EvemuReplayOptions {
    std::string events_path;
    std::string description_path;  // empty: the recording's header, else a .desc beside it
    bool loop = false;             // start again after the last event (soak runs)
    double loop_gap_s = 1.0;       // recorded seconds between the last event and the restart
    double time_scale = 1.0;       // kiosk seconds per recorded second (2: half speed)
};

class EvemuReplay {
  public:
    // Errors name the file, and the line for a damaged one.
    static Result<EvemuReplay> open(const EvemuReplayOptions& options);

    void set_mapping(const TouchMapping& mapping) { mapping_ = mapping; }
    // The recording's first event becomes due at now_s.
    void start(double now_s);
    bool started() const { return started_; }
    // When poll() next has something to do, on the kiosk's clock; infinity when finished or
    // not started.
    double next_due_s() const;
    // Plays every event due by now_s; times in the results are kiosk times.
    std::vector<InputEvent> poll(double now_s);
    bool finished() const;

    const std::string& device_name() const { return device_name_; }
    DeviceKind kind() const { return kind_; }
    const TouchAxes& axes() const { return axes_; }
    std::size_t event_count() const { return events_.size(); }

  private:
    EvemuReplay(EvemuReplayOptions options, std::string device_name, DeviceKind kind,
                const TouchAxes& axes, std::vector<input_event> events);
    double due_s(std::size_t index) const;
    void apply_to_state(const input_event& event);
    void restart_loop();

    EvemuReplayOptions options_;
    std::string device_name_;
    DeviceKind kind_;
    TouchAxes axes_;
    std::vector<input_event> events_;  // recorded times
    TouchMapping mapping_;
    DeviceDecoder decoder_;
    TouchSnapshot state_;  // the device as the kernel would hold it

    bool started_ = false;
    std::size_t next_ = 0;
    double start_s_ = 0.0;          // kiosk time of the current pass's first event
    double recorded_origin_s_ = 0;  // recorded time of the first event
};

}  // namespace gem::kiosk
