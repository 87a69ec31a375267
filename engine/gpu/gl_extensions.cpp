#include "gpu/gl_extensions.hpp"

#include <GLES3/gl3.h>

namespace gem::gpu {

bool gl_has_extension(std::string_view name) {
    GLint count = 0;
    glGetIntegerv(GL_NUM_EXTENSIONS, &count);
    for (GLint i = 0; i < count; ++i) {
        const auto* listed = reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, i));
        if (listed != nullptr && name == listed) return true;
    }
    return false;
}

}  // namespace gem::gpu
