#pragma once
// A linked GLSL ES program built from the embedded sources (shader_sources.hpp). Every stage
// starts with its "#version" (3.00 but where a feature needs 3.10), high precision and the given
// #defines, then the named chunks in order. Compile and link failures name the program, the stage
// and its files, and carry the driver's log.

#include <cstdint>
#include <functional>
#include <initializer_list>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include <GLES3/gl3.h>
#include <glm/glm.hpp>

#include "gpu/gl_handles.hpp"
#include "gpu/shader_sources.hpp"
#include "util/result.hpp"

namespace gem::gpu {

struct ProgramSpec {
    std::string name;                   // for messages: "table"
    std::vector<std::string> vertex;    // chunk names, main file last
    std::vector<std::string> fragment;  // chunk names, main file last
    std::vector<std::string> defines;   // "NON_CONVEX", "LIGHT_COUNT 2"
    // The ShaderFeature bits its sources test (program_variants.hpp): the tests build every
    // combination.
    std::uint32_t features = 0;
    // "300 es"; "310 es" where the sources need OpenGL ES 3.1 (glsl_version() in
    // program_variants.hpp), built only on a context that has it.
    std::string glsl_version = "300 es";
    // A program's own sources (a kiosk pass's, kiosk/passes/shaders), looked up before the
    // engine's; null: the engine's alone.
    const std::vector<ShaderSource>* sources = nullptr;
};

class Program {
  public:
    static Result<Program> build(const ProgramSpec& spec);

    GLuint id() const { return program_.get(); }
    const std::string& name() const { return name_; }
    // The location resolved when the program linked; -1 where its sources declare the name but
    // the GL dropped it (compiled out by a variant's defines, or unused). A name its sources do
    // not declare is a stale or misspelt one: -1 too, and recorded (take_unknown_uniforms).
    GLint uniform(const char* name) const;

    // Setters on the program in use (its pass's pipeline, pipeline.hpp); a location of -1 is
    // skipped, as GL does.
    void set(const char* name, int v) const { glUniform1i(uniform(name), v); }
    void set(const char* name, std::uint32_t v) const { glUniform1ui(uniform(name), v); }
    void set(const char* name, float v) const { glUniform1f(uniform(name), v); }
    void set(const char* name, const glm::vec2& v) const { glUniform2fv(uniform(name), 1, &v.x); }
    void set(const char* name, const glm::vec3& v) const { glUniform3fv(uniform(name), 1, &v.x); }
    void set(const char* name, const glm::vec4& v) const { glUniform4fv(uniform(name), 1, &v.x); }
    void set(const char* name, const glm::mat2& m) const {
        glUniformMatrix2fv(uniform(name), 1, GL_FALSE, &m[0][0]);
    }
    void set(const char* name, const glm::mat3& m) const {
        glUniformMatrix3fv(uniform(name), 1, GL_FALSE, &m[0][0]);
    }
    void set(const char* name, const glm::mat4& m) const {
        glUniformMatrix4fv(uniform(name), 1, GL_FALSE, &m[0][0]);
    }

  private:
    Program() = default;
    void resolve_uniforms(std::vector<std::string> declared);
    ProgramHandle program_;
    std::string name_;
    // Looked up by the caller's string without making a std::string of it (heterogeneous
    // lookup): a name longer than the small-string buffer would otherwise allocate on every
    // uniform set of every frame. Every name its sources declare, -1 where the GL has none.
    struct NameHash {
        using is_transparent = void;
        std::size_t operator()(std::string_view s) const noexcept {
            return std::hash<std::string_view>{}(s);
        }
    };
    std::unordered_map<std::string, GLint, NameHash, std::equal_to<>> locations_;
};

// Every "program 'x' sets 'u_y', which its sources do not declare" since the last call, once
// each, and forgets them: the GL tests' main (tests/support/gl_test_main.cpp) fails a test
// that leaves one.
std::vector<std::string> take_unknown_uniforms();

// The text of one embedded source, `own` (ProgramSpec::sources) searched before the engine's;
// an error names a missing one.
Result<std::string_view> shader_text(std::string_view name,
                                     const std::vector<ShaderSource>* own = nullptr);

}  // namespace gem::gpu
