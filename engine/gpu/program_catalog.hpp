#pragma once
// Every GPU program the renderer links, by name, so each pass asks for its program here and
// the tests can compile all of them (they must build as plain GLSL ES 3.00).

#include <string>
#include <vector>

#include "gpu/program.hpp"

namespace gem::gpu {

// The passes' programs ("background", "ring", "finish", ...: program_catalog.cpp), then each
// stone method's own ("trace", "trace_non_convex", "table", ...: its registry entry,
// stone_method.hpp).
std::vector<ProgramSpec> all_program_specs();
// A stone method's fragment shader: the shading, what a piece's still frames follow through
// the piece (stone_sight.glsl), then the method's own file. Every stone method draws the stone
// pass (stone.vert, stone_geometry.hpp) and reads the facets from stone.glsl.
std::vector<std::string> stone_method_sources(const char* main_file);
// `defines` are added to the program's own; `glsl_version` as ProgramSpec's.
Result<Program> build_program(const std::string& name, const std::vector<std::string>& defines = {},
                              const std::string& glsl_version = "300 es");

}  // namespace gem::gpu
