#include "gpu/egl_context.hpp"

#include <cstdio>
#include <cstring>
#include <utility>
#include <vector>

#include <EGL/eglext.h>
#include <GLES3/gl3.h>

namespace gem::gpu {
namespace {

Error egl_failure(const char* call) {
    return Error{std::string("EGL: ") + call + " failed: " + egl_error_name(eglGetError())};
}

bool has_extension(const char* list, const char* name) {
    if (list == nullptr) return false;
    const std::size_t n = std::strlen(name);
    for (const char* p = std::strstr(list, name); p != nullptr; p = std::strstr(p + n, name)) {
        if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
    }
    return false;
}

// ES 3.0 exactly: what the product promises to run on (embedded GPUs).
constexpr EGLint kContextAttributes[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 0,
                                         EGL_NONE};

}  // namespace

std::string egl_error_name(EGLint code) {
    const char* name = "unknown EGL error";
    switch (code) {
        case EGL_SUCCESS:
            name = "EGL_SUCCESS";
            break;
        case EGL_NOT_INITIALIZED:
            name = "EGL_NOT_INITIALIZED";
            break;
        case EGL_BAD_ACCESS:
            name = "EGL_BAD_ACCESS";
            break;
        case EGL_BAD_ALLOC:
            name = "EGL_BAD_ALLOC";
            break;
        case EGL_BAD_ATTRIBUTE:
            name = "EGL_BAD_ATTRIBUTE";
            break;
        case EGL_BAD_CONFIG:
            name = "EGL_BAD_CONFIG";
            break;
        case EGL_BAD_CONTEXT:
            name = "EGL_BAD_CONTEXT";
            break;
        case EGL_BAD_CURRENT_SURFACE:
            name = "EGL_BAD_CURRENT_SURFACE";
            break;
        case EGL_BAD_DISPLAY:
            name = "EGL_BAD_DISPLAY";
            break;
        case EGL_BAD_MATCH:
            name = "EGL_BAD_MATCH";
            break;
        case EGL_BAD_NATIVE_PIXMAP:
            name = "EGL_BAD_NATIVE_PIXMAP";
            break;
        case EGL_BAD_NATIVE_WINDOW:
            name = "EGL_BAD_NATIVE_WINDOW";
            break;
        case EGL_BAD_PARAMETER:
            name = "EGL_BAD_PARAMETER";
            break;
        case EGL_BAD_SURFACE:
            name = "EGL_BAD_SURFACE";
            break;
        case EGL_CONTEXT_LOST:
            name = "EGL_CONTEXT_LOST";
            break;
        default:
            break;
    }
    char code_text[16];
    std::snprintf(code_text, sizeof code_text, "0x%04X", static_cast<unsigned>(code));
    return std::string(name) + " (" + code_text + ")";
}

Result<EglContext> EglContext::headless() {
    EglContext ctx;
    const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (has_extension(client, "EGL_MESA_platform_surfaceless")) {
        auto get_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
            eglGetProcAddress("eglGetPlatformDisplayEXT"));
        if (get_display != nullptr) {
            ctx.display_ = get_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        }
    }
    if (ctx.display_ == EGL_NO_DISPLAY) ctx.display_ = eglGetDisplay(EGL_DEFAULT_DISPLAY);
    if (ctx.display_ == EGL_NO_DISPLAY)
        return Error{"EGL: no display (is Mesa's libEGL installed?)"};
    EGLint major = 0;
    EGLint minor = 0;
    if (!eglInitialize(ctx.display_, &major, &minor)) return egl_failure("eglInitialize");
    if (!eglBindAPI(EGL_OPENGL_ES_API)) return egl_failure("eglBindAPI");

    const EGLint config_attributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_ES3_BIT, EGL_SURFACE_TYPE,
                                        EGL_PBUFFER_BIT, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint configs = 0;
    if (!eglChooseConfig(ctx.display_, config_attributes, &config, 1, &configs) || configs == 0) {
        return Error{"EGL: no OpenGL ES 3 pbuffer configuration on this display"};
    }
    ctx.context_ = eglCreateContext(ctx.display_, config, EGL_NO_CONTEXT, kContextAttributes);
    if (ctx.context_ == EGL_NO_CONTEXT) return egl_failure("eglCreateContext (OpenGL ES 3.0)");
    const char* display_extensions = eglQueryString(ctx.display_, EGL_EXTENSIONS);
    if (!has_extension(display_extensions, "EGL_KHR_surfaceless_context")) {
        const EGLint pbuffer[] = {EGL_WIDTH, 1, EGL_HEIGHT, 1, EGL_NONE};
        ctx.surface_ = eglCreatePbufferSurface(ctx.display_, config, pbuffer);
        if (ctx.surface_ == EGL_NO_SURFACE) return egl_failure("eglCreatePbufferSurface");
    }
    if (!eglMakeCurrent(ctx.display_, ctx.surface_, ctx.surface_, ctx.context_)) {
        return egl_failure("eglMakeCurrent");
    }
    return ctx;
}

Result<EglContext> EglContext::window(EGLenum platform, void* native_display, void* native_window,
                                      EGLint native_visual) {
    EglContext ctx;
    ctx.window_ = true;
    auto get_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
        eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (get_display == nullptr) return Error{"EGL: eglGetPlatformDisplayEXT is missing"};
    ctx.display_ = get_display(platform, native_display, nullptr);
    if (ctx.display_ == EGL_NO_DISPLAY) return egl_failure("eglGetPlatformDisplayEXT");
    EGLint major = 0;
    EGLint minor = 0;
    if (!eglInitialize(ctx.display_, &major, &minor)) return egl_failure("eglInitialize");
    if (!eglBindAPI(EGL_OPENGL_ES_API)) return egl_failure("eglBindAPI");
    const EGLint config_attributes[] = {EGL_RENDERABLE_TYPE,
                                        EGL_OPENGL_ES3_BIT,
                                        EGL_SURFACE_TYPE,
                                        EGL_WINDOW_BIT,
                                        EGL_RED_SIZE,
                                        8,
                                        EGL_GREEN_SIZE,
                                        8,
                                        EGL_BLUE_SIZE,
                                        8,
                                        EGL_NONE};
    // Every matching config: EGL sorts deeper colour first, so a fixed-size list can hold only
    // 10-bit and float configs and miss the 8-bit one the display's format needs.
    EGLint count = 0;
    if (!eglChooseConfig(ctx.display_, config_attributes, nullptr, 0, &count) || count == 0) {
        return Error{"EGL: no OpenGL ES 3 window configuration on this display"};
    }
    std::vector<EGLConfig> configs(static_cast<std::size_t>(count));
    if (!eglChooseConfig(ctx.display_, config_attributes, configs.data(), count, &count)) {
        return egl_failure("eglChooseConfig");
    }
    EGLConfig chosen = configs[0];
    if (native_visual != 0) {
        chosen = nullptr;
        for (EGLint i = 0; i < count && chosen == nullptr; ++i) {
            EGLint visual = 0;
            eglGetConfigAttrib(ctx.display_, configs[i], EGL_NATIVE_VISUAL_ID, &visual);
            if (visual == native_visual) chosen = configs[i];
        }
        if (chosen == nullptr) return Error{"EGL: no configuration matches the display format"};
    }
    ctx.context_ = eglCreateContext(ctx.display_, chosen, EGL_NO_CONTEXT, kContextAttributes);
    if (ctx.context_ == EGL_NO_CONTEXT) return egl_failure("eglCreateContext (OpenGL ES 3.0)");
    auto create_surface = reinterpret_cast<PFNEGLCREATEPLATFORMWINDOWSURFACEEXTPROC>(
        eglGetProcAddress("eglCreatePlatformWindowSurfaceEXT"));
    if (create_surface == nullptr)
        return Error{"EGL: eglCreatePlatformWindowSurfaceEXT is missing"};
    ctx.surface_ = create_surface(ctx.display_, chosen, native_window, nullptr);
    ctx.buffer_age_ =
        has_extension(eglQueryString(ctx.display_, EGL_EXTENSIONS), "EGL_EXT_buffer_age");
    if (ctx.surface_ == EGL_NO_SURFACE) return egl_failure("eglCreatePlatformWindowSurfaceEXT");
    if (!eglMakeCurrent(ctx.display_, ctx.surface_, ctx.surface_, ctx.context_)) {
        return egl_failure("eglMakeCurrent");
    }
    return ctx;
}

EglContext::EglContext(EglContext&& other) noexcept {
    *this = std::move(other);
}

EglContext& EglContext::operator=(EglContext&& other) noexcept {
    if (this != &other) {
        release();
        display_ = std::exchange(other.display_, EGL_NO_DISPLAY);
        context_ = std::exchange(other.context_, EGL_NO_CONTEXT);
        surface_ = std::exchange(other.surface_, EGL_NO_SURFACE);
        window_ = std::exchange(other.window_, false);
        buffer_age_ = std::exchange(other.buffer_age_, false);
    }
    return *this;
}

EglContext::~EglContext() {
    release();
}

void EglContext::release() {
    if (display_ == EGL_NO_DISPLAY) return;
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (surface_ != EGL_NO_SURFACE) eglDestroySurface(display_, surface_);
    if (context_ != EGL_NO_CONTEXT) eglDestroyContext(display_, context_);
    eglTerminate(display_);
    display_ = EGL_NO_DISPLAY;
    context_ = EGL_NO_CONTEXT;
    surface_ = EGL_NO_SURFACE;
}

Result<bool> EglContext::swap_buffers() const {
    if (!window_) return true;
    if (!eglSwapBuffers(display_, surface_)) return egl_failure("eglSwapBuffers");
    return true;
}

std::optional<int> EglContext::buffer_age() const {
    if (!window_ || !buffer_age_) return std::nullopt;
    EGLint age = 0;
    if (!eglQuerySurface(display_, surface_, EGL_BUFFER_AGE_EXT, &age)) return std::nullopt;
    return static_cast<int>(age);
}

std::string EglContext::description() const {
    auto text = [](GLenum what) {
        const auto* s = reinterpret_cast<const char*>(glGetString(what));
        return std::string(s != nullptr ? s : "?");
    };
    return text(GL_RENDERER) + " | " + text(GL_VERSION);
}

}  // namespace gem::gpu
