#include "gpu/program.hpp"

#include <algorithm>
#include <cctype>
#include <mutex>
#include <utility>

#include "gpu/shader_sources.hpp"

namespace gem::gpu {
namespace {

std::mutex unknown_mutex;
std::vector<std::string> unknown_names;

bool word_char(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_';
}

// The word at `at` after any whitespace, `at` moved past it; empty where none starts there.
std::string_view next_word(std::string_view text, std::size_t& at) {
    while (at < text.size() && std::isspace(static_cast<unsigned char>(text[at])) != 0) ++at;
    const std::size_t start = at;
    while (at < text.size() && word_char(text[at])) ++at;
    return text.substr(start, at - start);
}

// The names a chunk declares as plain uniforms ("uniform highp vec3 u_eye;", arrays too), in
// every branch of its #ifs: a variant's defines decide which the GL keeps. A uniform block
// ("uniform StoneFacets {") has no name of its own to set: its members go through its buffer.
void add_declared(std::string_view chunk, std::vector<std::string>& declared) {
    constexpr std::string_view kUniform = "uniform";
    for (std::size_t at = chunk.find(kUniform); at != std::string_view::npos;
         at = chunk.find(kUniform, at)) {
        const bool starts_word = at == 0 || !word_char(chunk[at - 1]);
        at += kUniform.size();
        if (!starts_word || (at < chunk.size() && word_char(chunk[at]))) continue;
        std::string_view type = next_word(chunk, at);
        if (type == "lowp" || type == "mediump" || type == "highp") type = next_word(chunk, at);
        const std::string_view name = next_word(chunk, at);
        std::size_t after = at;
        while (after < chunk.size() && std::isspace(static_cast<unsigned char>(chunk[after])) != 0)
            ++after;
        if (type.empty() || name.empty() || after == chunk.size()) continue;
        if (chunk[after] == ';' || chunk[after] == '[') declared.emplace_back(name);
    }
}

std::string join(const std::vector<std::string>& names) {
    std::string out;
    for (const std::string& n : names) out += (out.empty() ? "" : "+") + n;
    return out;
}

std::string info_log(GLuint object, bool program) {
    GLint length = 0;
    program ? glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length)
            : glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<std::size_t>(length > 0 ? length : 1), '\0');
    GLsizei written = 0;
    program ? glGetProgramInfoLog(object, length, &written, log.data())
            : glGetShaderInfoLog(object, length, &written, log.data());
    log.resize(static_cast<std::size_t>(written));
    while (!log.empty() && (log.back() == '\n' || log.back() == '\0')) log.pop_back();
    return log;
}

// Compiles one stage; the shader object is returned on success and deleted on failure.
Result<GLuint> compile(const ProgramSpec& spec, GLenum stage, const std::vector<std::string>& names,
                       std::vector<std::string>& declared) {
    const char* stage_name = stage == GL_VERTEX_SHADER ? "vertex" : "fragment";
    const std::string where =
        "program '" + spec.name + "', " + stage_name + " shader " + join(names);
    // Every stage sees the same header; "#line 1 N" restarts line numbers per chunk, so the
    // driver's "0:12" reads as chunk 0, line 12 and the log below names the chunks in order.
    std::string text = "#version " + spec.glsl_version +
                       "\nprecision highp float;\nprecision highp int;\n"
                       "precision highp sampler2D;\nprecision highp usampler2D;\n"
                       "precision highp isampler2D;\nprecision highp samplerCube;\n"
                       "precision highp usamplerCube;\n";
    for (const std::string& d : spec.defines) text += "#define " + d + "\n";
    for (std::size_t i = 0; i < names.size(); ++i) {
        auto chunk = shader_text(names[i], spec.sources);
        if (!chunk) return Error{where + ": " + chunk.error()};
        add_declared(chunk.value(), declared);
        text += "#line 1 " + std::to_string(i) + "\n";
        text += chunk.value();
        text += "\n";
    }
    const GLuint shader = glCreateShader(stage);
    const char* source = text.c_str();
    glShaderSource(shader, 1, &source, nullptr);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (ok != GL_TRUE) {
        std::string log = info_log(shader, false);
        glDeleteShader(shader);
        return Error{where + " does not compile (source N = chunk N above):\n" + log};
    }
    return shader;
}

}  // namespace

Result<std::string_view> shader_text(std::string_view name, const std::vector<ShaderSource>* own) {
    if (own != nullptr) {
        for (const ShaderSource& s : *own) {
            if (s.name == name) return s.text;
        }
    }
    for (const ShaderSource& s : shader_sources()) {
        if (s.name == name) return s.text;
    }
    return Error{"no embedded shader named '" + std::string(name) + "'"};
}

Result<Program> Program::build(const ProgramSpec& spec) {
    std::vector<std::string> declared;
    auto vertex = compile(spec, GL_VERTEX_SHADER, spec.vertex, declared);
    if (!vertex) return Error{vertex.error()};
    auto fragment = compile(spec, GL_FRAGMENT_SHADER, spec.fragment, declared);
    if (!fragment) {
        glDeleteShader(vertex.value());
        return Error{fragment.error()};
    }
    Program p;
    p.name_ = spec.name;
    p.program_ = ProgramHandle(glCreateProgram());
    glAttachShader(p.program_.get(), vertex.value());
    glAttachShader(p.program_.get(), fragment.value());
    glLinkProgram(p.program_.get());
    // Shaders are flagged for deletion now and go with the program.
    glDeleteShader(vertex.value());
    glDeleteShader(fragment.value());
    GLint ok = GL_FALSE;
    glGetProgramiv(p.program_.get(), GL_LINK_STATUS, &ok);
    if (ok != GL_TRUE) {
        return Error{"program '" + spec.name + "' does not link:\n" +
                     info_log(p.program_.get(), true)};
    }
    p.resolve_uniforms(std::move(declared));
    return p;
}

void Program::resolve_uniforms(std::vector<std::string> declared) {
    std::sort(declared.begin(), declared.end());
    declared.erase(std::unique(declared.begin(), declared.end()), declared.end());
    for (std::string& name : declared) {
        const GLint location = glGetUniformLocation(program_.get(), name.c_str());
        locations_.emplace(std::move(name), location);
    }
}

GLint Program::uniform(const char* name) const {
    auto it = locations_.find(std::string_view(name));
    if (it != locations_.end()) return it->second;
    const std::string unknown =
        "program '" + name_ + "' sets '" + name + "', which its sources do not declare";
    const std::lock_guard lock(unknown_mutex);
    if (std::find(unknown_names.begin(), unknown_names.end(), unknown) == unknown_names.end()) {
        unknown_names.push_back(unknown);
    }
    return -1;
}

std::vector<std::string> take_unknown_uniforms() {
    const std::lock_guard lock(unknown_mutex);
    return std::exchange(unknown_names, {});
}

}  // namespace gem::gpu
