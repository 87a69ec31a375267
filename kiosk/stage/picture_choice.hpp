#pragma once
// The [picture] config and a look's exposure, as the GPU's picture takes them, and the
// [render] config as a scene takes it.

#include "gpu/hdr_picture.hpp"
#include "settings/kiosk_config.hpp"
#include "stage/stone_scene.hpp"

namespace gem::kiosk {

DisplayTransform display_transform(const PictureConfig& picture, const LookChoice& look);
gpu::PictureOptions picture_options(const PictureConfig& picture);
// The [render] config as a scene takes it; render.method "auto" draws with the table until the
// probe has chosen (probe/auto_method.hpp).
RenderChoice render_choice(const KioskConfig& config);

}  // namespace gem::kiosk
