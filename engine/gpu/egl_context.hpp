#pragma once
// The one EGL setup every program shares: an OpenGL ES 3.0 context, current on the calling
// thread. Headless programs and tests use Mesa's surfaceless platform (no display, no GPU
// needed: llvmpipe renders), falling back to the default display with a 1×1 pbuffer; the
// kiosk makes a window surface on a GBM device (docs/design.md, "Layout": display).

#include <optional>
#include <string>

#include <EGL/egl.h>

#include "util/result.hpp"

namespace gem::gpu {

class EglContext {
  public:
    // Errors say which EGL call failed and its error code's name.
    static Result<EglContext> headless();
    // A window surface on a native platform display (e.g. EGL_PLATFORM_GBM_KHR with a
    // gbm_device and gbm_surface); the surface's config must match `native_visual`
    // (a GBM format) when it is non-zero.
    static Result<EglContext> window(EGLenum platform, void* native_display, void* native_window,
                                     EGLint native_visual);

    EglContext(EglContext&& other) noexcept;
    EglContext& operator=(EglContext&& other) noexcept;
    EglContext(const EglContext&) = delete;
    EglContext& operator=(const EglContext&) = delete;
    ~EglContext();

    // Presents the window surface; a no-op headless. Errors name the EGL error.
    Result<bool> swap_buffers() const;
    // How many frames ago the window surface's back buffer was drawn (EGL_EXT_buffer_age,
    // queried after it is bound for drawing): 0 when its content is undefined. Nullopt where
    // EGL cannot say (no extension, no window): the whole buffer must then be drawn.
    std::optional<int> buffer_age() const;
    // "llvmpipe (LLVM 15.0.6, 256 bits) | OpenGL ES 3.2 Mesa 22.3.6"
    std::string description() const;
    EGLDisplay display() const { return display_; }

  private:
    EglContext() = default;
    void release();

    EGLDisplay display_ = EGL_NO_DISPLAY;
    EGLContext context_ = EGL_NO_CONTEXT;
    EGLSurface surface_ = EGL_NO_SURFACE;
    bool window_ = false;
    bool buffer_age_ = false;  // EGL_EXT_buffer_age on a window surface
};

// "EGL_BAD_ALLOC (0x3003)".
std::string egl_error_name(EGLint code);

}  // namespace gem::gpu
