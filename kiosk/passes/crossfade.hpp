#pragma once
// The short cross-fade when a preset or stone changes: the last picture before the change is
// held, and for `duration` seconds it is laid over the new frames with falling opacity
// (linear in time), so backgrounds and lights never switch with a jump.

#include "gpu/program.hpp"
#include "gpu/render_target.hpp"
#include "util/result.hpp"

namespace gem::kiosk {

class CrossFade {
  public:
    static Result<CrossFade> make(int width, int height);

    // Holds the current picture (call before drawing the first changed frame).
    void hold(const gpu::RenderTarget& picture, double now_s, double duration_s);
    bool active(double now_s) const { return now_s < end_s_; }
    // Opacity of the held picture at `now_s`: 1 at hold(), 0 from the end on.
    double opacity(double now_s) const;
    // Lays the held picture over `picture` (bound) if the fade is active.
    Result<bool> draw(const gpu::RenderTarget& picture, double now_s) const;

  private:
    CrossFade(gpu::Program program, gpu::RenderTarget held)
        : program_(std::move(program)), held_(std::move(held)) {}
    gpu::Program program_;
    gpu::RenderTarget held_;
    gpu::VertexArray empty_;
    double start_s_ = 0.0;
    double end_s_ = 0.0;
};

}  // namespace gem::kiosk
