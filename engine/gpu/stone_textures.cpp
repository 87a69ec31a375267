#include "gpu/stone_textures.hpp"

#include <algorithm>
#include <vector>

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

Result<StoneTextures> StoneTextures::upload(const Stone& stone) {
    StoneTextures out;
    out.convex_ = stone.convex;
    out.facets_ = static_cast<int>(stone.facets.size());
    std::vector<float> planes;
    planes.reserve(stone.facets.size() * 4);
    for (const Facet& f : stone.facets) {
        planes.insert(planes.end(),
                      {static_cast<float>(f.plane.n.x), static_cast<float>(f.plane.n.y),
                       static_cast<float>(f.plane.n.z), static_cast<float>(f.plane.d)});
    }
    auto p = upload_texel_array(planes.data(), stone.facets.size(), "stone facet planes");
    if (!p) return Error{p.error()};
    out.planes_ = std::move(p).value();
    // Convex stones need no triangles (obstruction is the facet test, tracing clips planes),
    // but every sampler must have a texture bound, so they get an empty one.
    if (stone.convex) {
        const float none[4] = {0.0f, 0.0f, 0.0f, 0.0f};
        auto t = upload_texel_array(none, 1, "stone triangles");
        if (!t) return Error{t.error()};
        out.triangles_texture_ = std::move(t).value();
    } else {
        out.triangles_ = static_cast<int>(stone.triangles.size());
        std::vector<float> corners;
        corners.reserve(stone.triangles.size() * 12);
        for (const MeshTriangle& tri : stone.triangles) {
            for (int k = 0; k < 3; ++k) {
                const glm::dvec3& v = stone.vertices[tri.v[k]];
                corners.insert(corners.end(),
                               {static_cast<float>(v.x), static_cast<float>(v.y),
                                static_cast<float>(v.z), static_cast<float>(tri.facet)});
            }
        }
        auto t = upload_texel_array(corners.data(), stone.triangles.size() * 3, "stone triangles");
        if (!t) return Error{t.error()};
        out.triangles_texture_ = std::move(t).value();
    }
    return out;
}

void StoneTextures::bind(const Program& program, int unit) const {
    glActiveTexture(GL_TEXTURE0 + unit);
    glBindTexture(GL_TEXTURE_2D, planes_.get());
    program.set("u_planes", unit);
    glActiveTexture(GL_TEXTURE0 + unit + 1);
    glBindTexture(GL_TEXTURE_2D, triangles_texture_.get());
    program.set("u_triangles", unit + 1);
    program.set("u_triangle_count", triangles_);
    program.set("u_facet_count", facets_);
}

}  // namespace gem::gpu
