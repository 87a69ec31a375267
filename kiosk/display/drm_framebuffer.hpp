#pragma once
// KMS framebuffers for GBM buffers. The framebuffer id is kept on the buffer object itself
// (gbm_bo_set_user_data) and removed when GBM destroys the buffer, so the framebuffer lives
// exactly as long as the buffer, with no table to keep in step (kmscube's drm_fb_get_from_bo).

#include <cstdint>

struct gbm_bo;

namespace gem::kiosk {

// The framebuffer id for `bo` on the card `fd`, made on first use; 0 when drmModeAddFB2 fails
// (errno says why).
std::uint32_t framebuffer_for(int fd, gbm_bo* bo);

}  // namespace gem::kiosk
