#include "gpu/background_pass.hpp"

#include "gpu/frame_uniforms.hpp"
#include "gpu/gl_check.hpp"
#include "gpu/pipeline.hpp"
#include "gpu/program_catalog.hpp"

namespace gem::gpu {

BackgroundPass::BackgroundPass(Program program)
    : program_(std::move(program)), empty_(make_vertex_array()) {}

Result<BackgroundPass> BackgroundPass::make() {
    auto p = build_program("background");
    if (!p) return Error{p.error()};
    return BackgroundPass(std::move(p).value());
}

Result<bool> BackgroundPass::draw(const Camera& camera, const EnvironmentCube& environment,
                                  std::optional<glm::vec3> colour) const {
    if (colour) {
        glClearColor(colour->x, colour->y, colour->z, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        return gl_check("background clear");
    }
    const PipelineScope pass(Pipeline{&program_});
    set_ray_uniforms(program_, camera);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_CUBE_MAP, environment.texture());
    program_.set("u_environment", 0);
    glBindVertexArray(empty_.get());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    return gl_check("background pass");
}

}  // namespace gem::gpu
