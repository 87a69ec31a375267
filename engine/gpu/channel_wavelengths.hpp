#pragma once
// The wavelengths at which the GPU methods evaluate dispersion per colour channel: the
// dominant wavelengths of the sRGB primaries (R 612, G 549, B 465 nm).

#include <glm/glm.hpp>

#include "optics/material.hpp"

namespace gem::gpu {

inline constexpr double kChannelNm[3] = {612.0, 549.0, 465.0};

// The material's refractive index at each channel's wavelength.
inline glm::vec3 channel_indices(const Material& material) {
    return {static_cast<float>(material.index(kChannelNm[0])),
            static_cast<float>(material.index(kChannelNm[1])),
            static_cast<float>(material.index(kChannelNm[2]))};
}

}  // namespace gem::gpu
