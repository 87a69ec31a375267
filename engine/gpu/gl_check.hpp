#pragma once
// GL error reporting: every pass checks once at its end and names itself, so a failing
// render says which pass broke and how ("table pass: GL_INVALID_OPERATION (0x0502)").

#include <string>
#include <string_view>

#include <GLES3/gl3.h>

#include "util/result.hpp"

namespace gem::gpu {

std::string gl_error_name(GLenum code);

// Drains the GL error queue; an error names `where` and every error code seen. A view, so the
// passes that check every frame build no string unless something went wrong.
Result<bool> gl_check(std::string_view where);

}  // namespace gem::gpu
