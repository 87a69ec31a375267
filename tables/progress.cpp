#include "progress.hpp"

#include <unistd.h>

#include <string>

namespace gem::tables {

namespace {

std::string clock_text(double seconds) {
    const auto s = static_cast<long long>(seconds + 0.5);
    char text[32];
    std::snprintf(text, sizeof text, "%lld:%02lld:%02lld", s / 3600, s / 60 % 60, s % 60);
    return text;
}

}  // namespace

Progress::Progress(std::uint64_t total, bool terminal, std::FILE* out)
    : total_(total == 0 ? 1 : total), terminal_(terminal), out_(out) {}

bool Progress::stdout_is_terminal() {
    return ::isatty(STDOUT_FILENO) == 1;
}

void Progress::advance(std::uint64_t done) {
    std::lock_guard lock(mutex_);
    done_ += done;
    draw();
}

void Progress::finish() {
    std::lock_guard lock(mutex_);
    if (terminal_) std::fputc('\n', out_);
    std::fflush(out_);
}

void Progress::draw() {
    const auto now = std::chrono::steady_clock::now();
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    const double share = static_cast<double>(done_) / static_cast<double>(total_);
    const double eta = done_ > 0 ? elapsed * (1.0 - share) / share : 0.0;
    if (terminal_) {
        // Redraw at most 10 times a second; the terminal is slower than the tracer.
        if (done_ < total_ && now - last_draw_ < std::chrono::milliseconds(100)) return;
        last_draw_ = now;
        constexpr int kWidth = 40;
        const int filled = static_cast<int>(share * kWidth);
        std::string bar(static_cast<std::size_t>(filled), '#');
        bar.resize(kWidth, '.');
        std::fprintf(out_, "\r[%s] %3d%% %llu/%llu  elapsed %s  ETA %s ", bar.c_str(),
                     static_cast<int>(share * 100.0), static_cast<unsigned long long>(done_),
                     static_cast<unsigned long long>(total_), clock_text(elapsed).c_str(),
                     clock_text(eta).c_str());
        std::fflush(out_);
        return;
    }
    const int tenth = static_cast<int>(share * 10.0);
    if (tenth <= last_tenth_) return;
    last_tenth_ = tenth;
    std::fprintf(out_, "gemtables: %d%% (%llu/%llu tables), elapsed %.1f s, ETA %.1f s\n",
                 tenth * 10, static_cast<unsigned long long>(done_),
                 static_cast<unsigned long long>(total_), elapsed, eta);
    std::fflush(out_);
}

}  // namespace gem::tables
