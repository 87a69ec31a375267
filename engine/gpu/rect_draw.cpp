#include "gpu/rect_draw.hpp"

namespace gem::gpu {

RectDraw::RectDraw() : vertex_array_(make_vertex_array()), buffer_(make_buffer()) {
    glBindVertexArray(vertex_array_.get());
    glBindBuffer(GL_ARRAY_BUFFER, buffer_.get());
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, nullptr);
    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
}

void RectDraw::draw(const std::vector<PixelRect>& rects, glm::ivec2 size) {
    scratch_.clear();
    const float sx = 2.0f / static_cast<float>(size.x), sy = 2.0f / static_cast<float>(size.y);
    for (const PixelRect& r : rects) {
        if (r.empty()) continue;
        const float x0 = static_cast<float>(r.x0) * sx - 1.0f;
        const float x1 = static_cast<float>(r.x1) * sx - 1.0f;
        const float y0 = static_cast<float>(r.y0) * sy - 1.0f;
        const float y1 = static_cast<float>(r.y1) * sy - 1.0f;
        scratch_.insert(scratch_.end(), {x0, y0, x1, y0, x1, y1, x0, y0, x1, y1, x0, y1});
    }
    if (scratch_.empty()) return;
    glBindVertexArray(vertex_array_.get());
    glBindBuffer(GL_ARRAY_BUFFER, buffer_.get());
    // New storage each draw, not glBufferSubData: the last draw may still read the old (a
    // frame's passes queue behind each other), and writing into it would wait for that.
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(scratch_.size() * sizeof(float)),
                 scratch_.data(), GL_STREAM_DRAW);
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(scratch_.size() / 2));
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glBindVertexArray(0);
}

}  // namespace gem::gpu
