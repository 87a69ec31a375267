#include "display/drm_commit.hpp"

#include <xf86drm.h>

#include "display/drm_probe.hpp"

namespace gem::kiosk {
namespace {

// Atomic KMS (Documentation/gpu/drm-kms.rst, "Atomic Mode Setting"; drm_mode.h for the
// flags): every change is a set of (object, property, value) triples committed at once.
class AtomicCommit final : public KmsCommit {
  public:
    explicit AtomicCommit(const KmsOutput& output) : out_(output) {}
    ~AtomicCommit() override {
        if (mode_blob_ != 0) drmModeDestroyPropertyBlob(out_.fd, mode_blob_);
    }

    bool init() {
        plane_ = primary_plane();
        if (plane_ == 0) return false;
        connector_crtc_ = prop(out_.connector_id, DRM_MODE_OBJECT_CONNECTOR, "CRTC_ID");
        mode_id_ = prop(out_.crtc_id, DRM_MODE_OBJECT_CRTC, "MODE_ID");
        active_ = prop(out_.crtc_id, DRM_MODE_OBJECT_CRTC, "ACTIVE");
        const char* names[] = {"FB_ID", "CRTC_ID", "SRC_X",  "SRC_Y",  "SRC_W",
                               "SRC_H", "CRTC_X",  "CRTC_Y", "CRTC_W", "CRTC_H"};
        for (int i = 0; i < 10; ++i)
            plane_props_[i] = prop(plane_, DRM_MODE_OBJECT_PLANE, names[i]);
        if (connector_crtc_ == 0 || mode_id_ == 0 || active_ == 0) return false;
        for (std::uint32_t id : plane_props_) {
            if (id == 0) return false;
        }
        return drmModeCreatePropertyBlob(out_.fd, &out_.mode, sizeof out_.mode, &mode_blob_) == 0;
    }

    int modeset(std::uint32_t fb) override {
        drmModeAtomicReq* req = drmModeAtomicAlloc();
        drmModeAtomicAddProperty(req, out_.connector_id, connector_crtc_, out_.crtc_id);
        drmModeAtomicAddProperty(req, out_.crtc_id, mode_id_, mode_blob_);
        drmModeAtomicAddProperty(req, out_.crtc_id, active_, 1);
        add_plane(req, fb);
        // Ask the driver first whether it takes this configuration at all, so a refusal
        // changes nothing on screen.
        int r = drmModeAtomicCommit(
            out_.fd, req, DRM_MODE_ATOMIC_TEST_ONLY | DRM_MODE_ATOMIC_ALLOW_MODESET, nullptr);
        if (r == 0) r = drmModeAtomicCommit(out_.fd, req, DRM_MODE_ATOMIC_ALLOW_MODESET, nullptr);
        drmModeAtomicFree(req);
        return r < 0 ? r : 0;
    }

    int flip(std::uint32_t fb, void* user_data) override {
        drmModeAtomicReq* req = drmModeAtomicAlloc();
        add_plane(req, fb);
        const int r = drmModeAtomicCommit(
            out_.fd, req, DRM_MODE_ATOMIC_NONBLOCK | DRM_MODE_PAGE_FLIP_EVENT, user_data);
        drmModeAtomicFree(req);
        return r < 0 ? r : 0;
    }

    const char* name() const override { return "atomic"; }

  private:
    std::uint32_t prop(std::uint32_t object, std::uint32_t type, const char* name_) const {
        return find_property(out_.fd, object, type, name_).id;
    }

    // The primary plane that can feed our CRTC; the one already on it if there is one.
    std::uint32_t primary_plane() const {
        drmModePlaneRes* planes = drmModeGetPlaneResources(out_.fd);
        if (planes == nullptr) return 0;
        std::uint32_t chosen = 0;
        for (std::uint32_t i = 0; i < planes->count_planes; ++i) {
            drmModePlane* plane = drmModeGetPlane(out_.fd, planes->planes[i]);
            if (plane == nullptr) continue;
            const bool usable = (plane->possible_crtcs & (1u << out_.crtc_index)) != 0;
            const bool on_crtc = plane->crtc_id == out_.crtc_id;
            const std::uint32_t id = plane->plane_id;
            drmModeFreePlane(plane);
            if (!usable) continue;
            if (find_property(out_.fd, id, DRM_MODE_OBJECT_PLANE, "type").value !=
                DRM_PLANE_TYPE_PRIMARY) {
                continue;
            }
            if (chosen == 0 || on_crtc) chosen = id;
            if (on_crtc) break;
        }
        drmModeFreePlaneResources(planes);
        return chosen;
    }

    void add_plane(drmModeAtomicReq* req, std::uint32_t fb) const {
        const std::uint64_t w = out_.mode.hdisplay;
        const std::uint64_t h = out_.mode.vdisplay;
        // SRC_* are 16.16 fixed point, CRTC_* whole pixels (drm_plane.c, "plane properties").
        const std::uint64_t values[10] = {fb, out_.crtc_id, 0, 0, w << 16, h << 16, 0, 0, w, h};
        for (int i = 0; i < 10; ++i)
            drmModeAtomicAddProperty(req, plane_, plane_props_[i], values[i]);
    }

    KmsOutput out_;
    std::uint32_t plane_ = 0;
    std::uint32_t connector_crtc_ = 0;
    std::uint32_t mode_id_ = 0;
    std::uint32_t active_ = 0;
    std::uint32_t plane_props_[10] = {};
    std::uint32_t mode_blob_ = 0;
};

// The pre-atomic interface: drmModeSetCrtc for the mode, drmModePageFlip per frame.
class LegacyCommit final : public KmsCommit {
  public:
    explicit LegacyCommit(const KmsOutput& output) : out_(output) {}
    int modeset(std::uint32_t fb) override {
        const int r =
            drmModeSetCrtc(out_.fd, out_.crtc_id, fb, 0, 0, &out_.connector_id, 1, &out_.mode);
        return r < 0 ? r : 0;
    }
    int flip(std::uint32_t fb, void* user_data) override {
        const int r =
            drmModePageFlip(out_.fd, out_.crtc_id, fb, DRM_MODE_PAGE_FLIP_EVENT, user_data);
        return r < 0 ? r : 0;
    }
    const char* name() const override { return "legacy"; }

  private:
    KmsOutput out_;
};

}  // namespace

std::unique_ptr<KmsCommit> make_atomic_commit(const KmsOutput& output) {
    // Universal planes first: atomic needs the primary plane as a plane object.
    if (drmSetClientCap(output.fd, DRM_CLIENT_CAP_UNIVERSAL_PLANES, 1) != 0) return nullptr;
    if (drmSetClientCap(output.fd, DRM_CLIENT_CAP_ATOMIC, 1) != 0) return nullptr;
    auto commit = std::make_unique<AtomicCommit>(output);
    if (!commit->init()) return nullptr;
    return commit;
}

std::unique_ptr<KmsCommit> make_legacy_commit(const KmsOutput& output) {
    return std::make_unique<LegacyCommit>(output);
}

}  // namespace gem::kiosk
