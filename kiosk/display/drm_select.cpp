#include "display/drm_select.hpp"

#include <cmath>
#include <cstdio>
#include <tuple>

#include <xf86drmMode.h>

namespace gem::kiosk {
namespace {

std::string list_connectors(const std::vector<ConnectorInfo>& connectors) {
    if (connectors.empty()) return "none";
    std::string text;
    for (const ConnectorInfo& c : connectors) {
        if (!text.empty()) text += ", ";
        text += c.name + (c.connected ? " (connected)" : " (disconnected)");
    }
    return text;
}

std::string list_modes(const ConnectorInfo& connector) {
    if (connector.modes.empty()) return "none";
    std::string text;
    for (const ModeInfo& m : connector.modes) {
        if (!text.empty()) text += ", ";
        text += describe_mode(m);
        if (m.preferred) text += " (preferred)";
    }
    return text;
}

// Without a request: the preferred mode (the panel's native timing, drm_modes.c marks it from
// the EDID's first detailed timing), else the largest progressive mode at its highest refresh.
std::optional<std::size_t> default_mode(const std::vector<ModeInfo>& modes) {
    for (std::size_t i = 0; i < modes.size(); ++i) {
        if (modes[i].preferred) return i;
    }
    std::optional<std::size_t> best;
    auto key = [&](const ModeInfo& m) {
        return std::make_tuple(!m.interlaced, static_cast<long>(m.hdisplay) * m.vdisplay,
                               mode_refresh_hz(m));
    };
    for (std::size_t i = 0; i < modes.size(); ++i) {
        if (!best || key(modes[i]) > key(modes[*best])) best = i;
    }
    return best;
}

std::optional<std::size_t> requested_mode(const std::vector<ModeInfo>& modes,
                                          const ModeRequest& request) {
    const std::string name = std::to_string(request.width) + "x" + std::to_string(request.height) +
                             (request.interlaced ? "i" : "");
    std::optional<std::size_t> best;
    double best_distance = 0.0;
    for (std::size_t i = 0; i < modes.size(); ++i) {
        const ModeInfo& m = modes[i];
        // Some drivers give interlaced modes their field height (the Xilinx listing in
        // tests/fixtures/drm/hdmi_interlaced.txt has "1920x1080i" with vdisplay 540), so the
        // kernel's mode name counts as well as the size.
        const bool same_size = m.hdisplay == request.width && m.vdisplay == request.height;
        if (m.interlaced != request.interlaced || !(same_size || m.name == name)) continue;
        const double hz = mode_refresh_hz(m);
        if (request.refresh_hz) {
            const double distance = std::abs(hz - *request.refresh_hz);
            // A request of "@60" means the 60.00 Hz mode, not 59.94 Hz, but also accepts
            // 59.94 Hz where that is all there is.
            if (distance > 0.5) continue;
            if (!best || distance < best_distance) {
                best = i;
                best_distance = distance;
            }
        } else {
            // Preferred first, then the highest refresh; the first listed on a tie.
            if (!best || (m.preferred && !modes[*best].preferred) ||
                (m.preferred == modes[*best].preferred && hz > mode_refresh_hz(modes[*best]))) {
                best = i;
            }
        }
    }
    return best;
}

}  // namespace

double mode_refresh_hz(const ModeInfo& mode) {
    if (mode.clock_khz <= 0 || mode.htotal <= 0 || mode.vtotal <= 0) return 0.0;
    double numerator = mode.clock_khz * 1000.0;
    double denominator = static_cast<double>(mode.htotal) * mode.vtotal;
    if (mode.interlaced) numerator *= 2.0;
    if (mode.doublescan) denominator *= 2.0;
    if (mode.vscan > 1) denominator *= mode.vscan;
    return numerator / denominator;
}

std::string describe_mode(const ModeInfo& mode) {
    char refresh[32];
    std::snprintf(refresh, sizeof refresh, "@%.2f", mode_refresh_hz(mode));
    if (!mode.name.empty()) return mode.name + refresh;
    return std::to_string(mode.hdisplay) + "x" + std::to_string(mode.vdisplay) +
           (mode.interlaced ? "i" : "") + refresh;
}

std::string connector_name(std::uint32_t connector_type, std::uint32_t type_id) {
    const char* type_name = drmModeGetConnectorTypeName(connector_type);
    const std::string type =
        type_name != nullptr ? std::string(type_name) : "Unknown" + std::to_string(connector_type);
    return type + "-" + std::to_string(type_id);
}

PanelOrientation panel_orientation_from_name(const std::string& enum_name) {
    // The enum names the kernel gives the property (drm_connector.c,
    // drm_panel_orientation_enum_list).
    if (enum_name == "Upside Down") return PanelOrientation::upside_down;
    if (enum_name == "Left Side Up") return PanelOrientation::left_side_up;
    if (enum_name == "Right Side Up") return PanelOrientation::right_side_up;
    return PanelOrientation::normal;
}

const char* panel_orientation_name(PanelOrientation orientation) {
    switch (orientation) {
        case PanelOrientation::upside_down:
            return "Upside Down";
        case PanelOrientation::left_side_up:
            return "Left Side Up";
        case PanelOrientation::right_side_up:
            return "Right Side Up";
        case PanelOrientation::normal:
            break;
    }
    return "Normal";
}

Result<ModeRequest> parse_mode_request(const std::string& text) {
    ModeRequest request;
    char interlace = 0;
    int consumed = 0;
    const Error bad{"display mode '" + text +
                    "': expected WIDTHxHEIGHT, WIDTHxHEIGHTi or either with @REFRESH "
                    "(e.g. 1920x1080@60)"};
    if (std::sscanf(text.c_str(), "%dx%d%n", &request.width, &request.height, &consumed) != 2) {
        return bad;
    }
    std::size_t at = static_cast<std::size_t>(consumed);
    if (at < text.size() && text[at] == 'i') {
        interlace = 'i';
        ++at;
    }
    request.interlaced = interlace == 'i';
    if (at < text.size()) {
        if (text[at] != '@') return bad;
        double hz = 0.0;
        int used = 0;
        const std::string rest = text.substr(at + 1);
        if (std::sscanf(rest.c_str(), "%lf%n", &hz, &used) != 1 ||
            static_cast<std::size_t>(used) != rest.size() || !(hz > 0.0)) {
            return bad;
        }
        request.refresh_hz = hz;
    }
    if (request.width <= 0 || request.height <= 0) return bad;
    return request;
}

Result<OutputChoice> choose_output(const std::vector<ConnectorInfo>& connectors,
                                   const DisplayOptions& options) {
    OutputChoice choice;
    bool found = false;
    if (!options.connector.empty()) {
        for (std::size_t i = 0; i < connectors.size() && !found; ++i) {
            if (connectors[i].name == options.connector) {
                choice.connector = i;
                found = true;
            }
        }
        if (!found) {
            return Error{"display connector '" + options.connector +
                         "' does not exist; connectors: " + list_connectors(connectors)};
        }
        if (!connectors[choice.connector].connected) {
            return Error{"display connector '" + options.connector +
                         "' has nothing connected; connectors: " + list_connectors(connectors)};
        }
    } else {
        for (std::size_t i = 0; i < connectors.size() && !found; ++i) {
            if (connectors[i].connected && !connectors[i].modes.empty()) {
                choice.connector = i;
                found = true;
            }
        }
        if (!found) {
            return Error{"no connected display; connectors: " + list_connectors(connectors)};
        }
    }
    const ConnectorInfo& connector = connectors[choice.connector];
    std::optional<std::size_t> mode;
    if (!options.mode.empty()) {
        auto request = parse_mode_request(options.mode);
        if (!request) return Error{request.error()};
        mode = requested_mode(connector.modes, request.value());
        if (!mode) {
            return Error{"display mode '" + options.mode + "' is not offered by " + connector.name +
                         "; modes: " + list_modes(connector)};
        }
    } else {
        mode = default_mode(connector.modes);
        if (!mode) return Error{"display connector " + connector.name + " reports no modes"};
    }
    choice.mode = *mode;
    return choice;
}

}  // namespace gem::kiosk
