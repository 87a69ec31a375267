# Writes OUTPUT: a C++ file that holds every shader in SHADER_DIR as a string, so programs
# need no files at run time. Run at build time (cmake -P) whenever a shader changes.
# FUNCTION and NAMESPACE name the function that returns them (default: the engine's
# gem::gpu::shader_sources); a program's own passes embed theirs under a name of their own.
if(NOT FUNCTION)
  set(FUNCTION shader_sources)
endif()
if(NOT NAMESPACE)
  set(NAMESPACE gem::gpu)
endif()
file(GLOB shaders RELATIVE ${SHADER_DIR} ${SHADER_DIR}/*.glsl ${SHADER_DIR}/*.vert
     ${SHADER_DIR}/*.frag)
list(SORT shaders)
set(body "// Generated from ${SHADER_DIR} by cmake/embed_shaders.cmake; do not edit.\n")
string(APPEND body "#include \"gpu/shader_sources.hpp\"\n\nnamespace ${NAMESPACE} {\n\n")
string(APPEND body "const std::vector<gem::gpu::ShaderSource>& ${FUNCTION}() {\n")
string(APPEND body "    static const std::vector<gem::gpu::ShaderSource> sources = {\n")
foreach(name ${shaders})
  file(READ ${SHADER_DIR}/${name} text)
  # A raw string with a delimiter no shader contains.
  string(APPEND body "        {\"${name}\", R\"gemshader(${text})gemshader\"},\n")
endforeach()
string(APPEND body "    };\n    return sources;\n}\n\n}  // namespace ${NAMESPACE}\n")
file(WRITE ${OUTPUT}.tmp "${body}")
file(COPY_FILE ${OUTPUT}.tmp ${OUTPUT} ONLY_IF_DIFFERENT)
