#include "display/drm_framebuffer.hpp"

#include <gbm.h>
#include <xf86drmMode.h>

namespace gem::kiosk {
namespace {

struct CachedFramebuffer {
    int fd;
    std::uint32_t id;
};

void destroy_framebuffer(gbm_bo* /*bo*/, void* data) {
    auto* fb = static_cast<CachedFramebuffer*>(data);
    if (fb->id != 0) drmModeRmFB(fb->fd, fb->id);
    delete fb;
}

}  // namespace

std::uint32_t framebuffer_for(int fd, gbm_bo* bo) {
    if (auto* cached = static_cast<CachedFramebuffer*>(gbm_bo_get_user_data(bo))) {
        return cached->id;
    }
    // One plane for XRGB8888 / ARGB8888; the handle, pitch and offset arrays are per plane.
    const std::uint32_t handles[4] = {gbm_bo_get_handle(bo).u32, 0, 0, 0};
    const std::uint32_t pitches[4] = {gbm_bo_get_stride(bo), 0, 0, 0};
    const std::uint32_t offsets[4] = {0, 0, 0, 0};
    std::uint32_t id = 0;
    if (drmModeAddFB2(fd, gbm_bo_get_width(bo), gbm_bo_get_height(bo), gbm_bo_get_format(bo),
                      handles, pitches, offsets, &id, 0) != 0) {
        return 0;
    }
    gbm_bo_set_user_data(bo, new CachedFramebuffer{fd, id}, destroy_framebuffer);
    return id;
}

}  // namespace gem::kiosk
