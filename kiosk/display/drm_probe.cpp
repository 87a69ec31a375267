#include "display/drm_probe.hpp"

#include <cerrno>
#include <cstring>
#include <memory>

namespace gem::kiosk {
namespace {

struct ResourcesDeleter {
    void operator()(drmModeRes* r) const { drmModeFreeResources(r); }
};
struct ConnectorDeleter {
    void operator()(drmModeConnector* c) const { drmModeFreeConnector(c); }
};
struct EncoderDeleter {
    void operator()(drmModeEncoder* e) const { drmModeFreeEncoder(e); }
};
using Resources = std::unique_ptr<drmModeRes, ResourcesDeleter>;
using Connector = std::unique_ptr<drmModeConnector, ConnectorDeleter>;
using Encoder = std::unique_ptr<drmModeEncoder, EncoderDeleter>;

PanelOrientation panel_orientation_of(int fd, std::uint32_t connector_id) {
    drmModeObjectProperties* props =
        drmModeObjectGetProperties(fd, connector_id, DRM_MODE_OBJECT_CONNECTOR);
    if (props == nullptr) return PanelOrientation::normal;
    PanelOrientation orientation = PanelOrientation::normal;
    for (std::uint32_t i = 0; i < props->count_props; ++i) {
        drmModePropertyRes* prop = drmModeGetProperty(fd, props->props[i]);
        if (prop == nullptr) continue;
        if (std::strcmp(prop->name, "panel orientation") == 0) {
            // An enum property: the value is one of the enums' values, named by the kernel.
            for (int e = 0; e < prop->count_enums; ++e) {
                if (prop->enums[e].value == props->prop_values[i]) {
                    orientation = panel_orientation_from_name(prop->enums[e].name);
                }
            }
        }
        drmModeFreeProperty(prop);
    }
    drmModeFreeObjectProperties(props);
    return orientation;
}

}  // namespace

ModeInfo mode_info_from(const drmModeModeInfo& mode) {
    ModeInfo m;
    m.name = std::string(mode.name, strnlen(mode.name, sizeof mode.name));
    m.hdisplay = mode.hdisplay;
    m.vdisplay = mode.vdisplay;
    m.clock_khz = static_cast<int>(mode.clock);
    m.htotal = mode.htotal;
    m.vtotal = mode.vtotal;
    m.vscan = mode.vscan;
    m.interlaced = (mode.flags & DRM_MODE_FLAG_INTERLACE) != 0;
    m.doublescan = (mode.flags & DRM_MODE_FLAG_DBLSCAN) != 0;
    m.preferred = (mode.type & DRM_MODE_TYPE_PREFERRED) != 0;
    return m;
}

Result<DrmOutputs> probe_outputs(int fd, const std::string& device, bool force_probe) {
    Resources resources(drmModeGetResources(fd));
    if (!resources) {
        return Error{device + ": not a modesetting device (drmModeGetResources: " +
                     std::strerror(errno) + ")"};
    }
    DrmOutputs outputs;
    for (int i = 0; i < resources->count_connectors; ++i) {
        const std::uint32_t id = resources->connectors[i];
        Connector connector(force_probe ? drmModeGetConnector(fd, id)
                                        : drmModeGetConnectorCurrent(fd, id));
        if (!connector) continue;
        ConnectorInfo info;
        info.name = connector_name(connector->connector_type, connector->connector_type_id);
        info.connected = connector->connection == DRM_MODE_CONNECTED;
        std::vector<drmModeModeInfo> modes(connector->modes,
                                           connector->modes + connector->count_modes);
        for (const drmModeModeInfo& mode : modes) info.modes.push_back(mode_info_from(mode));
        info.orientation = panel_orientation_of(fd, id);
        outputs.connectors.push_back(std::move(info));
        outputs.connector_ids.push_back(id);
        outputs.modes.push_back(std::move(modes));
    }
    return outputs;
}

Result<CrtcChoice> choose_crtc(int fd, std::uint32_t connector_id) {
    Resources resources(drmModeGetResources(fd));
    Connector connector(drmModeGetConnectorCurrent(fd, connector_id));
    if (!resources || !connector) {
        return Error{std::string("cannot read the card's resources: ") + std::strerror(errno)};
    }
    auto index_of = [&](std::uint32_t crtc_id) {
        for (int i = 0; i < resources->count_crtcs; ++i) {
            if (resources->crtcs[i] == crtc_id) return i;
        }
        return -1;
    };
    // The CRTC already lit for this connector (by the console or firmware) avoids a change.
    if (connector->encoder_id != 0) {
        Encoder encoder(drmModeGetEncoder(fd, connector->encoder_id));
        if (encoder && encoder->crtc_id != 0 && index_of(encoder->crtc_id) >= 0) {
            return CrtcChoice{encoder->crtc_id, index_of(encoder->crtc_id)};
        }
    }
    for (int e = 0; e < connector->count_encoders; ++e) {
        Encoder encoder(drmModeGetEncoder(fd, connector->encoders[e]));
        if (!encoder) continue;
        // possible_crtcs: bit i set when the encoder can take the i-th CRTC of the resources
        // (drm_mode.h, struct drm_mode_get_encoder).
        for (int i = 0; i < resources->count_crtcs; ++i) {
            if (encoder->possible_crtcs & (1u << i)) return CrtcChoice{resources->crtcs[i], i};
        }
    }
    return Error{"no CRTC can drive this connector"};
}

PropertyValue find_property(int fd, std::uint32_t object_id, std::uint32_t object_type,
                            const char* name) {
    PropertyValue found;
    drmModeObjectProperties* props = drmModeObjectGetProperties(fd, object_id, object_type);
    if (props == nullptr) return found;
    for (std::uint32_t i = 0; i < props->count_props && found.id == 0; ++i) {
        drmModePropertyRes* prop = drmModeGetProperty(fd, props->props[i]);
        if (prop == nullptr) continue;
        if (std::strcmp(prop->name, name) == 0) found = {prop->prop_id, props->prop_values[i]};
        drmModeFreeProperty(prop);
    }
    drmModeFreeObjectProperties(props);
    return found;
}

}  // namespace gem::kiosk
