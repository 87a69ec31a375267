#pragma once
// The display without a screen (CI, snapshots, benchmarks): an EGL surfaceless context, a
// picture of the configured size, and a frame due every 1/headless_rate_hz seconds from a
// timerfd (0 Hz: a frame is always due, so the loop renders as fast as it can).

#include <memory>

#include "display/display.hpp"
#include "display/display_options.hpp"

namespace gem::kiosk {

class HeadlessDisplay final : public Display {
  public:
    // Errors: a size below 1 pixel, a negative rate, no EGL, no timerfd.
    static Result<std::unique_ptr<HeadlessDisplay>> make(const DisplayOptions& options);
    ~HeadlessDisplay() override;
    HeadlessDisplay(const HeadlessDisplay&) = delete;
    HeadlessDisplay& operator=(const HeadlessDisplay&) = delete;

    glm::ivec2 picture_size() const override { return size_; }
    int rotation_deg() const override { return 0; }
    gpu::EglContext& context() override { return context_; }
    bool ready() const override { return frame_due_; }
    Result<bool> present(const gpu::RenderTarget& picture, const gpu::TileSet& changed) override;
    int event_fd() const override { return timer_fd_; }
    void dispatch() override;
    int timeout_ms() const override { return timer_fd_ < 0 ? 0 : -1; }
    double refresh_hz() const override { return rate_hz_; }
    std::string describe() const override;

    // Frames presented so far.
    long presented() const { return presented_; }

  private:
    HeadlessDisplay(gpu::EglContext context, glm::ivec2 size, double rate_hz, int timer_fd);

    gpu::EglContext context_;
    glm::ivec2 size_;
    double rate_hz_;
    int timer_fd_;
    bool frame_due_;
    long presented_ = 0;
};

}  // namespace gem::kiosk
