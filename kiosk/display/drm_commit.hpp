#pragma once
// Putting a framebuffer on screen, by atomic modesetting or the legacy calls, behind one small
// interface so the display does not care which (as kmscube's drm-atomic / drm-legacy and
// wlroots' crtc_commit do). Both return 0 or a negative errno, as libdrm does.

#include <cstdint>
#include <memory>

#include <xf86drmMode.h>

namespace gem::kiosk {

struct KmsOutput {
    int fd = -1;
    std::uint32_t connector_id = 0;
    std::uint32_t crtc_id = 0;
    int crtc_index = -1;
    drmModeModeInfo mode{};
};

class KmsCommit {
  public:
    virtual ~KmsCommit() = default;
    // Lights the connector with `fb` in the output's mode; blocking, no event.
    virtual int modeset(std::uint32_t fb) = 0;
    // Queues `fb` for the next vblank; a page-flip event carrying `user_data` follows.
    virtual int flip(std::uint32_t fb, void* user_data) = 0;
    virtual const char* name() const = 0;  // "atomic" / "legacy"
};

// Null when the driver does not do atomic modesetting or lacks a property it needs (the
// caller falls back to legacy). Sets DRM_CLIENT_CAP_ATOMIC on the fd.
std::unique_ptr<KmsCommit> make_atomic_commit(const KmsOutput& output);
std::unique_ptr<KmsCommit> make_legacy_commit(const KmsOutput& output);

}  // namespace gem::kiosk
