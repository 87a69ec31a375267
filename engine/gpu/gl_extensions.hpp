#pragma once
// Whether the current GL context offers an extension (glGetStringi over GL_EXTENSIONS) or an
// OpenGL ES version: what a pass may use beyond OpenGL ES 3.0 is asked for, never assumed.

#include <string_view>

namespace gem::gpu {

bool gl_has_extension(std::string_view name);
// The context is OpenGL ES major.minor or later.
bool gl_version_at_least(int major, int minor);

}  // namespace gem::gpu
