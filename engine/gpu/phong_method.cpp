#include "gpu/phong_method.hpp"

#include <string>
#include <vector>

#include "gpu/gl_check.hpp"
#include "gpu/program_catalog.hpp"

namespace gem::gpu {

PhongMethod::PhongMethod(Program program) : program_(std::move(program)) {}

Result<PhongMethod> PhongMethod::make(const Stone& stone) {
    // Position and facet normal per corner, interleaved; corners are not shared, so every
    // triangle is flat whatever its neighbours.
    std::vector<glm::vec3> data;
    data.reserve(stone.triangles.size() * 6);
    for (const MeshTriangle& t : stone.triangles) {
        if (t.facet >= stone.facets.size()) {
            return Error{"phong: stone '" + stone.name + "' has a triangle on facet " +
                         std::to_string(t.facet) + " of " + std::to_string(stone.facets.size())};
        }
        const glm::vec3 n(stone.facets[t.facet].plane.n);
        for (std::uint32_t v : t.v) {
            data.emplace_back(stone.vertices[v]);
            data.push_back(n);
        }
    }
    if (data.empty()) return Error{"phong: stone '" + stone.name + "' has no triangles"};
    auto program = build_program("phong");
    if (!program) return Error{program.error()};
    PhongMethod m(std::move(program).value());
    m.vertex_count_ = static_cast<GLsizei>(data.size() / 2);
    m.vertex_array_ = make_vertex_array();
    glBindVertexArray(m.vertex_array_.get());
    m.vertices_ = make_buffer();
    glBindBuffer(GL_ARRAY_BUFFER, m.vertices_.get());
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.size() * sizeof(glm::vec3)),
                 data.data(), GL_STATIC_DRAW);
    const GLsizei stride = 2 * sizeof(glm::vec3);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, nullptr);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride,
                          reinterpret_cast<const void*>(sizeof(glm::vec3)));
    glEnableVertexAttribArray(1);
    glBindVertexArray(0);
    auto ok = gl_check("phong: upload");
    if (!ok) return Error{ok.error()};
    return m;
}

Result<bool> PhongMethod::draw(const StoneFrame& frame) const {
    const Camera& camera = frame.camera;
    program_.use();
    program_.set("u_view_projection", view_projection(camera, frame.scene_radius_mm));
    const bool at_infinity = camera.orthographic();
    program_.set("u_eye", at_infinity ? glm::vec3(-camera.forward())
                                      : glm::vec3(-camera.forward() * camera.distance()));
    program_.set("u_eye_at_infinity", at_infinity ? 1 : 0);
    set_shading_uniforms(program_, frame, 0);
    glBindVertexArray(vertex_array_.get());
    glEnable(GL_CULL_FACE);
    glFrontFace(GL_CCW);
    glEnable(GL_DEPTH_TEST);

    // 1. Forget older depth inside the stone's outline (depth range [1, 1] writes the far
    //    plane), so the front pass below keeps the nearest front facet however the buffer
    //    started.
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_ALWAYS);
    glDepthRangef(1.0f, 1.0f);
    glCullFace(GL_BACK);
    glDrawArrays(GL_TRIANGLES, 0, vertex_count_);
    glDepthRangef(0.0f, 1.0f);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);

    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    // 2. Back facets, seen through the front ones: blended, no depth.
    glDepthMask(GL_FALSE);
    glCullFace(GL_FRONT);
    glDrawArrays(GL_TRIANGLES, 0, vertex_count_);
    // 3. Front facets over them, keeping their depth.
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
    glCullFace(GL_BACK);
    glDrawArrays(GL_TRIANGLES, 0, vertex_count_);

    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    glBindVertexArray(0);
    return gl_check("phong pass");
}

}  // namespace gem::gpu
