// libFuzzer target: any bytes handed to the kiosk's readers of its own surroundings, each
// input to all three: the config file (parse_config: toml++ and every key's reader), the last
// good config kept in the state folder (read_last_good_config), and an evemu recording with
// its device description (EvemuReplay::open: libevemu's reader, the device's classification
// and the recorded events). Each must answer with a value or an Error, never a crash, a
// sanitizer report, an assertion or a runaway allocation. Seeds: the shipped config, the test
// configs, tests/data/evemu and the recordings of tests/fixtures.
#include <stdlib.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

#include "input/evemu_replay.hpp"
#include "settings/kiosk_config.hpp"
#include "settings/last_good_config.hpp"

namespace {

// The folder the file readers' inputs are written to, one per process.
const std::filesystem::path& scratch() {
    static const std::filesystem::path dir = [] {
        std::string pattern = (std::filesystem::temp_directory_path() / "fuzz-config-XXXXXX");
        return std::filesystem::path(::mkdtemp(pattern.data()));
    }();
    return dir;
}

void write(const std::filesystem::path& file, std::string_view bytes) {
    std::ofstream(file, std::ios::binary | std::ios::trunc)
        .write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size > 64 * 1024) return 0;  // a config is a few kilobytes
    const std::string_view bytes(reinterpret_cast<const char*>(data), size);
    (void)gem::kiosk::parse_config(bytes, "fuzz.toml", "/etc/gemkiosk");

    write(scratch() / gem::kiosk::kLastGoodConfigName, bytes);
    if (auto kept = gem::kiosk::read_last_good_config(scratch())) {
        (void)gem::kiosk::parse_config(kept.value().text, "kept.toml", "/etc/gemkiosk");
    }

    // The input as a recording with its own header, then as the .desc of a recording of one
    // event (a description alone holds no events, so would stop before its reader).
    const std::filesystem::path input = scratch() / "fuzz.events";
    const std::filesystem::path one_event = scratch() / "one.events";
    write(input, bytes);
    write(one_event, "E: 0.000000 0000 0000 0000\n");
    for (const std::filesystem::path& recording : {input, one_event}) {
        gem::kiosk::EvemuReplayOptions replay;
        replay.events_path = recording.string();
        replay.description_path = input.string();
        if (auto opened = gem::kiosk::EvemuReplay::open(replay)) {
            opened.value().start(0.0);
            (void)opened.value().poll(1e9);
        }
    }
    return 0;
}
