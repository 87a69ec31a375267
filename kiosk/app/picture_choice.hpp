#pragma once
// The [picture] config and a look's exposure, as the GPU's picture takes them.

#include "app/stone_scene.hpp"
#include "gpu/hdr_picture.hpp"
#include "settings/kiosk_config.hpp"

namespace gem::kiosk {

DisplayTransform display_transform(const PictureConfig& picture, const LookChoice& look);
gpu::PictureOptions picture_options(const PictureConfig& picture);

}  // namespace gem::kiosk
