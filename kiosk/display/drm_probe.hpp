#pragma once
// Reading what a DRM card offers (connectors, their modes and properties, CRTCs) into the
// pure structures drm_select.hpp chooses from, with the kernel ids kept alongside.

#include <cstdint>
#include <string>
#include <vector>

#include <xf86drmMode.h>

#include "display/drm_select.hpp"
#include "util/result.hpp"

namespace gem::kiosk {

struct DrmOutputs {
    std::vector<ConnectorInfo> connectors;            // for choose_output()
    std::vector<std::uint32_t> connector_ids;         // same order
    std::vector<std::vector<drmModeModeInfo>> modes;  // same order, the kernel's mode structs
};

ModeInfo mode_info_from(const drmModeModeInfo& mode);

// Every connector of the card. `force_probe`: drmModeGetConnector (asks the hardware, may take
// a while); otherwise drmModeGetConnectorCurrent (the kernel's last known state, cheap, kept
// up to date by hotplug interrupts and the kernel's output polling).
Result<DrmOutputs> probe_outputs(int fd, const std::string& device, bool force_probe);

// A CRTC that can drive the connector (through one of its encoders' possible_crtcs, preferring
// the one the encoder already uses); its index in the resources' CRTC list too.
struct CrtcChoice {
    std::uint32_t crtc_id = 0;
    int crtc_index = -1;
};
Result<CrtcChoice> choose_crtc(int fd, std::uint32_t connector_id);

// A KMS object's property id by name (0: none) and its current value.
struct PropertyValue {
    std::uint32_t id = 0;
    std::uint64_t value = 0;
};
PropertyValue find_property(int fd, std::uint32_t object_id, std::uint32_t object_type,
                            const char* name);

}  // namespace gem::kiosk
