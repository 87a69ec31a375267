#pragma once
// A bench's frame: composed as the kiosk composes its own (gpu/frame_composer.hpp), the scene
// required (a bench has no surround to fall back on: the program stops with why).

#include "bench_support.hpp"
#include "gpu/frame_composer.hpp"

namespace gem::bench {

inline gpu::ComposedFrame compose(const char* program, const gpu::FrameRequest& request,
                                  const gpu::RenderTarget& target) {
    gpu::ComposedFrame frame = must(program, gpu::compose_frame(request, target));
    if (!frame.stats) fail(program, frame.scene_error);
    return frame;
}

}  // namespace gem::bench
