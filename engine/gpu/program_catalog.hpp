#pragma once
// Every GPU program the renderer links, by name, so each pass asks for its program here and
// the tests can compile all of them (they must build as plain GLSL ES 3.00).

#include <string>
#include <vector>

#include "gpu/program.hpp"

namespace gem::gpu {

// Names: "background", "table", "table_non_convex", "trace", "trace_non_convex", "phong",
// "ring", ... (see program_catalog.cpp).
std::vector<ProgramSpec> all_program_specs();
// `defines` are added to the program's own; `glsl_version` as ProgramSpec's.
Result<Program> build_program(const std::string& name, const std::vector<std::string>& defines = {},
                              const std::string& glsl_version = "300 es");

}  // namespace gem::gpu
