#pragma once
// The [picture] config and a look's exposure, as the GPU's picture takes them.

#include "gpu/hdr_picture.hpp"
#include "settings/kiosk_config.hpp"
#include "stage/stone_scene.hpp"

namespace gem::kiosk {

DisplayTransform display_transform(const PictureConfig& picture, const LookChoice& look);
gpu::PictureOptions picture_options(const PictureConfig& picture);

}  // namespace gem::kiosk
