#pragma once
// An independent, deliberately trivial reading of an evemu recording's "E:" lines, so that the
// tests' expected values come from the recording's own numbers, not from the code under test.

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace gem::kiosk::test {

struct RawEvent {
    double time_s = 0.0;
    int type = 0;
    int code = 0;
    int value = 0;
};

inline std::vector<RawEvent> read_raw_events(const std::string& path) {
    std::vector<RawEvent> events;
    std::ifstream stream(path);
    std::string line;
    while (std::getline(stream, line)) {
        if (line.rfind("E:", 0) != 0) continue;
        std::istringstream fields(line.substr(2));
        std::string time, type, code;
        RawEvent event;
        fields >> time >> type >> code >> event.value;
        const std::size_t dot = time.find('.');
        event.time_s = std::stod(time.substr(0, dot)) + std::stod(time.substr(dot + 1)) * 1e-6;
        event.type = std::stoi(type, nullptr, 16);
        event.code = std::stoi(code, nullptr, 16);
        events.push_back(event);
    }
    return events;
}

}  // namespace gem::kiosk::test
