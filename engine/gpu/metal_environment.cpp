#include "gpu/metal_environment.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "gpu/framebuffer_scope.hpp"
#include "gpu/gl_check.hpp"
#include "gpu/pipeline.hpp"
#include "gpu/program_catalog.hpp"
#include "optics/microfacet.hpp"

namespace gem::gpu {

namespace {

constexpr int kBrdfTableSize = 32;

// Integrated once a process (about 50 ms on one core): every renderer shares the numbers.
const std::vector<float>& brdf_table_values() {
    static const std::vector<float> values = environment_brdf_table(kBrdfTableSize);
    return values;
}

Result<bool> filter(const EnvironmentCube& source, EnvironmentCube& target, double roughness) {
    auto program = build_program("metal_filter");
    if (!program) return Error{program.error()};
    const FramebufferScope restore;
    Framebuffer framebuffer = make_framebuffer();
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.get());
    glViewport(0, 0, target.face_size(), target.face_size());
    const PipelineScope pass(Pipeline{&program.value()});
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_CUBE_MAP, source.texture());
    program.value().set("u_source", 0);
    program.value().set("u_source_face", static_cast<float>(source.face_size()));
    program.value().set("u_alpha", static_cast<float>(ggx_alpha(roughness)));
    VertexArray empty = make_vertex_array();  // fullscreen.vert needs no attributes
    glBindVertexArray(empty.get());
    for (int face = 0; face < 6; ++face) {
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                               GL_TEXTURE_CUBE_MAP_POSITIVE_X + face, target.texture(), 0);
        if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
            return Error{"metal environment: cube face " + std::to_string(face) +
                         " cannot be rendered to"};
        }
        const CubeFaceBasis basis = cube_face_basis(face);
        program.value().set("u_forward", glm::vec3(basis.forward));
        program.value().set("u_right", glm::vec3(basis.right));
        program.value().set("u_up", glm::vec3(basis.up));
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, 0, 0);
    return gl_check("metal environment: filter");
}

}  // namespace

int metal_environment_face(double roughness, int source_face) {
    // The reflected lobe spans about 2·alpha radians each side; a face spans pi/2.
    const double lobe = 2.0 * ggx_alpha(roughness);
    const double wanted = 4.0 * (0.5 * 3.14159265358979323846) / lobe;
    int face = 8;
    while (face < wanted && face < source_face) face *= 2;
    return std::min(face, source_face);
}

Result<MetalEnvironment> MetalEnvironment::make(const EnvironmentCube& environment,
                                                double roughness) {
    MetalEnvironment m;
    m.source_ = &environment;
    m.brdf_table_ = make_texture_2d(GL_RG16F, kBrdfTableSize, kBrdfTableSize, GL_LINEAR);
    // Float data into a half-float texture (ES 3.0 table 3.2 allows RG16F from GL_FLOAT).
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, kBrdfTableSize, kBrdfTableSize, GL_RG, GL_FLOAT,
                    brdf_table_values().data());
    if (roughness >= kSmoothRoughness) {
        auto cube =
            EnvironmentCube::allocate(metal_environment_face(roughness, environment.face_size()));
        if (!cube) return Error{cube.error()};
        m.filtered_ = std::make_unique<EnvironmentCube>(std::move(cube).value());
        auto filtered = filter(environment, *m.filtered_, roughness);
        if (!filtered) return Error{filtered.error()};
    }
    auto ok = gl_check("metal environment");
    if (!ok) return Error{ok.error()};
    return m;
}

}  // namespace gem::gpu
