#include "gpu/gl_check.hpp"

#include <cstdio>

namespace gem::gpu {

std::string gl_error_name(GLenum code) {
    const char* name = "unknown GL error";
    switch (code) {
        case GL_NO_ERROR:
            name = "GL_NO_ERROR";
            break;
        case GL_INVALID_ENUM:
            name = "GL_INVALID_ENUM";
            break;
        case GL_INVALID_VALUE:
            name = "GL_INVALID_VALUE";
            break;
        case GL_INVALID_OPERATION:
            name = "GL_INVALID_OPERATION";
            break;
        case GL_INVALID_FRAMEBUFFER_OPERATION:
            name = "GL_INVALID_FRAMEBUFFER_OPERATION";
            break;
        case GL_OUT_OF_MEMORY:
            name = "GL_OUT_OF_MEMORY";
            break;
        default:
            break;
    }
    char code_text[16];
    std::snprintf(code_text, sizeof code_text, "0x%04X", code);
    return std::string(name) + " (" + code_text + ")";
}

Result<bool> gl_check(std::string_view where) {
    std::string seen;
    // A lost context can report errors forever; a handful is enough to say what happened.
    for (int i = 0; i < 8; ++i) {
        const GLenum code = glGetError();
        if (code == GL_NO_ERROR) break;
        seen += (seen.empty() ? "" : ", ") + gl_error_name(code);
    }
    if (seen.empty()) return true;
    return Error{std::string(where) + ": " + seen};
}

}  // namespace gem::gpu
