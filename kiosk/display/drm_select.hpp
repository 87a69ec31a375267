#pragma once
// Choosing the output: which connector and which of its modes the kiosk drives, from what the
// kernel reports (connectors with their mode lists) and the [display] options. Pure logic, so
// it is tested against connector lists recorded on real machines (tests/fixtures/drm/).

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "display/display_options.hpp"
#include "util/result.hpp"

namespace gem::kiosk {

// One display mode as the kernel reports it (struct drm_mode_modeinfo in drm_mode.h).
struct ModeInfo {
    std::string name;  // "1920x1080", "1920x1080i"
    int hdisplay = 0;
    int vdisplay = 0;
    int clock_khz = 0;  // pixel clock
    int htotal = 0;
    int vtotal = 0;
    int vscan = 0;            // lines scanned per line; 0 and 1 mean once
    bool interlaced = false;  // DRM_MODE_FLAG_INTERLACE
    bool doublescan = false;  // DRM_MODE_FLAG_DBLSCAN
    bool preferred = false;   // DRM_MODE_TYPE_PREFERRED
};

// The connector property "panel orientation": how the panel sits in the casing
// (kernel drm_connector.c, "standard connector properties"; enum drm_panel_orientation).
enum class PanelOrientation { normal, upside_down, left_side_up, right_side_up };

struct ConnectorInfo {
    std::string name;  // "HDMI-A-1": connector type name + "-" + type id
    bool connected = false;
    std::vector<ModeInfo> modes;
    PanelOrientation orientation = PanelOrientation::normal;
};

struct OutputChoice {
    std::size_t connector = 0;  // index into the list given
    std::size_t mode = 0;       // index into that connector's modes
};

// "WxH", "WxHi" (interlaced) or either with "@R" (Hz).
struct ModeRequest {
    int width = 0;
    int height = 0;
    bool interlaced = false;
    std::optional<double> refresh_hz;
};

// The vertical refresh in Hz from the mode's timings, as the kernel's drm_mode_vrefresh()
// (drivers/gpu/drm/drm_modes.c) computes it: clock * 1000 / (htotal * vtotal), doubled for
// interlaced modes (two fields per frame: the rate is the field rate, which is the rate of
// vblanks and page flips), halved for double scan and divided by vscan. 0 when the timings
// are missing.
double mode_refresh_hz(const ModeInfo& mode);

// "1920x1080@60.00": the kernel's mode name (WxH, "i" for interlaced) and the refresh.
std::string describe_mode(const ModeInfo& mode);

// The kernel's and libdrm's name: drmModeGetConnectorTypeName(type) + "-" + type_id, e.g.
// "HDMI-A-1", "eDP-1"; "Unknown<type>-<id>" for a type libdrm does not know.
std::string connector_name(std::uint32_t connector_type, std::uint32_t type_id);

PanelOrientation panel_orientation_from_name(const std::string& enum_name);
const char* panel_orientation_name(PanelOrientation orientation);

Result<ModeRequest> parse_mode_request(const std::string& text);

// The connector: options.connector by name, else the first connected one. The mode:
// options.mode ("WxH" picks the preferred mode of that size if there is one, else its highest
// refresh; "WxH@R" the mode of that size whose refresh is nearest R, within 0.5 Hz), else the
// connector's preferred mode, else its largest progressive mode with the highest refresh.
// Errors name what was asked for and list what exists.
Result<OutputChoice> choose_output(const std::vector<ConnectorInfo>& connectors,
                                   const DisplayOptions& options);

}  // namespace gem::kiosk
