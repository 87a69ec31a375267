#include "gpu/environment_cube.hpp"

#include <vector>

#include "gpu/gl_check.hpp"
#include "gpu/gl_extensions.hpp"

namespace gem::gpu {

CubeFaceBasis cube_face_basis(int face) {
    // s grows along `right` and t along `up`: a face rendered with this basis into a GL
    // framebuffer (row 0 at the bottom) reads back with rows in the face's memory order.
    const glm::dvec3 centre = cube_face_direction(face, 0.5, 0.5);
    const glm::dvec3 right = cube_face_direction(face, 1.0, 0.5) * std::sqrt(2.0) - centre;
    const glm::dvec3 up = cube_face_direction(face, 0.5, 1.0) * std::sqrt(2.0) - centre;
    return {centre, glm::normalize(right), glm::normalize(up)};
}

bool renders_half_float() {
    return gl_has_extension("GL_EXT_color_buffer_half_float") ||
           gl_has_extension("GL_EXT_color_buffer_float");
}

Result<EnvironmentCube> EnvironmentCube::allocate(int face_size) {
    if (face_size < 1 || face_size > 4096) {
        return Error{"environment cube: face size " + std::to_string(face_size) +
                     " is outside 1..4096"};
    }
    EnvironmentCube cube;
    cube.face_size_ = face_size;
    cube.texture_ = make_texture();
    glBindTexture(GL_TEXTURE_CUBE_MAP, cube.texture_.get());
    const bool half_float = renders_half_float();
    for (int face = 0; face < 6; ++face) {
        if (half_float) {
            glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face, 0, GL_RGBA16F, face_size, face_size,
                         0, GL_RGBA, GL_HALF_FLOAT, nullptr);
        } else {
            glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face, 0, GL_SRGB8_ALPHA8, face_size,
                         face_size, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
        }
    }
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    cube.sharp_sampler_ = make_sampler(GL_LINEAR);
    auto ok = gl_check("environment cube: allocate");
    if (!ok) return Error{ok.error()};
    return cube;
}

Result<EnvironmentCube> EnvironmentCube::from_environment(const Environment& environment,
                                                          int face_size) {
    auto cube = allocate(face_size);
    if (!cube) return cube;
    std::vector<glm::vec4> texels(static_cast<std::size_t>(face_size) * face_size);
    glBindTexture(GL_TEXTURE_CUBE_MAP, cube.value().texture());
    for (int face = 0; face < 6; ++face) {
        for (int t = 0; t < face_size; ++t) {
            for (int s = 0; s < face_size; ++s) {
                const glm::dvec3 d =
                    cube_face_direction(face, (s + 0.5) / face_size, (t + 0.5) / face_size);
                texels[static_cast<std::size_t>(t) * face_size + s] =
                    glm::vec4(glm::vec3(environment.radiance(d)), 1.0f);
            }
        }
        // Float data into a half-float texture: GL converts (ES 3.0 table 3.2 allows
        // RGBA16F from GL_FLOAT).
        glTexSubImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face, 0, 0, 0, face_size, face_size,
                        GL_RGBA, GL_FLOAT, texels.data());
    }
    // Box-filtered levels for blurred lookups (the ring's rough metal); sharp lookups name
    // level 0.
    glGenerateMipmap(GL_TEXTURE_CUBE_MAP);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    auto ok = gl_check("environment cube: upload");
    if (!ok) return Error{ok.error()};
    return cube;
}

}  // namespace gem::gpu
