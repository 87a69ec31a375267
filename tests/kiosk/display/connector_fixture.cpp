#include "connector_fixture.hpp"

#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

namespace gem::kiosk::test {

RecordedConnectors read_recorded_connectors(const std::string& file_name) {
    RecordedConnectors recorded;
    const std::string path = std::string(GEM_FIXTURES_DIR) + "/drm/" + file_name;
    std::ifstream in(path);
    if (!in) {
        ADD_FAILURE() << "cannot read " << path;
        return recorded;
    }
    std::string line;
    int number = 0;
    while (std::getline(in, line)) {
        ++number;
        if (line.empty() || line[0] == '#') continue;
        std::istringstream words(line);
        std::string keyword;
        words >> keyword;
        const std::string where = path + ":" + std::to_string(number);
        if (keyword == "connector") {
            ConnectorInfo c;
            std::string state;
            words >> c.name >> state;
            if (state != "connected" && state != "disconnected") {
                ADD_FAILURE() << where << ": bad connector state '" << state << "'";
            }
            c.connected = state == "connected";
            recorded.connectors.push_back(c);
            recorded.printed_refresh.emplace_back();
            continue;
        }
        if (recorded.connectors.empty()) {
            ADD_FAILURE() << where << ": line before any connector";
            continue;
        }
        ConnectorInfo& c = recorded.connectors.back();
        if (keyword == "orientation") {
            std::string name;
            std::getline(words >> std::ws, name);
            c.orientation = panel_orientation_from_name(name);
            if (name != panel_orientation_name(c.orientation)) {
                ADD_FAILURE() << where << ": unknown orientation '" << name << "'";
            }
        } else if (keyword == "mode") {
            ModeInfo m;
            double printed = 0.0;
            int hss = 0, hse = 0, vss = 0, vse = 0;
            words >> m.name >> printed >> m.hdisplay >> hss >> hse >> m.htotal >> m.vdisplay >>
                vss >> vse >> m.vtotal >> m.clock_khz;
            if (!words) ADD_FAILURE() << where << ": malformed mode line";
            std::string rest;
            std::getline(words, rest);
            // modetest prints the flag and type names of drm_mode.h ("interlace", "dblscan",
            // "preferred").
            const auto type_at = rest.find("type:");
            const std::string flags = rest.substr(0, type_at);
            const std::string type = type_at == std::string::npos ? "" : rest.substr(type_at);
            m.interlaced = flags.find("interlace") != std::string::npos;
            m.doublescan = flags.find("dblscan") != std::string::npos;
            m.preferred = type.find("preferred") != std::string::npos;
            c.modes.push_back(m);
            recorded.printed_refresh.back().push_back(printed);
        } else {
            ADD_FAILURE() << where << ": unknown line '" << keyword << "'";
        }
    }
    return recorded;
}

}  // namespace gem::kiosk::test
