#include "display/headless_display.hpp"

#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>

#include <sys/timerfd.h>
#include <unistd.h>

namespace gem::kiosk {

Result<std::unique_ptr<HeadlessDisplay>> HeadlessDisplay::make(const DisplayOptions& options) {
    if (options.headless_width < 1 || options.headless_height < 1) {
        return Error{"headless display: size " + std::to_string(options.headless_width) + "x" +
                     std::to_string(options.headless_height) + " must be at least 1x1"};
    }
    if (!(options.headless_rate_hz >= 0.0) || !std::isfinite(options.headless_rate_hz)) {
        return Error{"headless display: rate " + std::to_string(options.headless_rate_hz) +
                     " Hz must be 0 (unpaced) or more"};
    }
    auto context = gpu::EglContext::headless();
    if (!context) return Error{"headless display: " + context.error()};
    int timer_fd = -1;
    if (options.headless_rate_hz > 0.0) {
        timer_fd = timerfd_create(CLOCK_MONOTONIC, TFD_NONBLOCK | TFD_CLOEXEC);
        if (timer_fd < 0) {
            return Error{std::string("headless display: timerfd_create failed: ") +
                         std::strerror(errno)};
        }
        const auto period_ns = static_cast<long long>(std::llround(1e9 / options.headless_rate_hz));
        itimerspec spec{};
        spec.it_interval.tv_sec = static_cast<time_t>(period_ns / 1000000000LL);
        spec.it_interval.tv_nsec = static_cast<long>(period_ns % 1000000000LL);
        if (spec.it_interval.tv_sec == 0 && spec.it_interval.tv_nsec == 0)
            spec.it_interval.tv_nsec = 1;
        spec.it_value = spec.it_interval;
        if (timerfd_settime(timer_fd, 0, &spec, nullptr) != 0) {
            const int error = errno;
            close(timer_fd);
            return Error{std::string("headless display: timerfd_settime failed: ") +
                         std::strerror(error)};
        }
    }
    return std::unique_ptr<HeadlessDisplay>(new HeadlessDisplay(
        std::move(context).value(), {options.headless_width, options.headless_height},
        options.headless_rate_hz, timer_fd));
}

HeadlessDisplay::HeadlessDisplay(gpu::EglContext context, glm::ivec2 size, double rate_hz,
                                 int timer_fd)
    : context_(std::move(context)),
      size_(size),
      rate_hz_(rate_hz),
      timer_fd_(timer_fd),
      // The first frame is due at once; later ones when the timer fires.
      frame_due_(true) {}

HeadlessDisplay::~HeadlessDisplay() {
    if (timer_fd_ >= 0) close(timer_fd_);
}

Result<bool> HeadlessDisplay::present(const gpu::RenderTarget& picture,
                                      const gpu::TileSet& changed) {
    (void)changed;  // the picture itself is what a headless display shows
    if (picture.width() != size_.x || picture.height() != size_.y) {
        return Error{"headless display: picture is " + std::to_string(picture.width()) + "x" +
                     std::to_string(picture.height()) + ", the display " + std::to_string(size_.x) +
                     "x" + std::to_string(size_.y)};
    }
    ++presented_;
    if (timer_fd_ >= 0) frame_due_ = false;
    return true;
}

void HeadlessDisplay::dispatch() {
    if (timer_fd_ < 0) return;
    std::uint64_t expirations = 0;
    // Non-blocking: EAGAIN when the timer has not fired since the last read.
    if (read(timer_fd_, &expirations, sizeof expirations) == sizeof expirations &&
        expirations > 0) {
        frame_due_ = true;
    }
}

std::string HeadlessDisplay::describe() const {
    char rate[32];
    std::snprintf(rate, sizeof rate, "%g Hz", rate_hz_);
    return "headless " + std::to_string(size_.x) + "x" + std::to_string(size_.y) + " " +
           (timer_fd_ < 0 ? std::string("unpaced") : std::string(rate));
}

}  // namespace gem::kiosk
