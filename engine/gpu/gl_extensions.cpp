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

bool gl_version_at_least(int major, int minor) {
    GLint has_major = 0, has_minor = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &has_major);
    glGetIntegerv(GL_MINOR_VERSION, &has_minor);
    return has_major > major || (has_major == major && has_minor >= minor);
}

}  // namespace gem::gpu
