#pragma once
// Whether the current GL context offers an extension (glGetStringi over GL_EXTENSIONS): what a
// pass may use beyond OpenGL ES 3.0 is asked for by name, never assumed.

#include <string_view>

namespace gem::gpu {

bool gl_has_extension(std::string_view name);

}  // namespace gem::gpu
