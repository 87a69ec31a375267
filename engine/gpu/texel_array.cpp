#include "gpu/texel_array.hpp"

#include <algorithm>

#include "gpu/gl_check.hpp"

namespace gem::gpu {

Result<Texture> upload_texel_array(const float* rgba, std::size_t texels, const char* what) {
    GLint max_size = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
    const std::size_t rows = std::max<std::size_t>(1, (texels + kTextureWidth - 1) / kTextureWidth);
    if (rows > static_cast<std::size_t>(max_size)) {
        return Error{std::string(what) + ": " + std::to_string(texels) +
                     " texels exceed the GPU's texture size limit"};
    }
    // Whole rows straight from `rgba`, then the partial last row: no padded copy (a view's
    // rays are tens of megabytes).
    const std::size_t full_rows = texels / kTextureWidth;
    const std::size_t rest = texels % kTextureWidth;
    Texture t = make_texture();
    glBindTexture(GL_TEXTURE_2D, t.get());
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, kTextureWidth, static_cast<GLsizei>(rows), 0,
                 GL_RGBA, GL_FLOAT, nullptr);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    if (full_rows > 0) {
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, kTextureWidth, static_cast<GLsizei>(full_rows),
                        GL_RGBA, GL_FLOAT, rgba);
    }
    if (rest > 0) {
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, static_cast<GLint>(full_rows),
                        static_cast<GLsizei>(rest), 1, GL_RGBA, GL_FLOAT,
                        rgba + full_rows * kTextureWidth * 4);
    }
    // RGBA32F is not filterable in ES 3.0: nearest only, read with texelFetch.
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    auto ok = gl_check(what);
    if (!ok) return Error{ok.error()};
    return t;
}

}  // namespace gem::gpu
