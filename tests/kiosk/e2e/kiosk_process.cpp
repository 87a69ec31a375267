#include "kiosk_process.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>

namespace gem::kiosk_e2e {

KioskProcess::KioskProcess(const std::vector<std::string>& arguments) {
    int pipe_fds[2];
    if (::pipe2(pipe_fds, O_CLOEXEC) != 0) return;
    pid_ = ::fork();
    if (pid_ == 0) {
        ::dup2(pipe_fds[1], STDERR_FILENO);
        ::dup2(pipe_fds[1], STDOUT_FILENO);
        std::vector<char*> argv;
        for (const std::string& a : arguments) argv.push_back(const_cast<char*>(a.c_str()));
        argv.push_back(nullptr);
        ::execv(argv[0], argv.data());
        ::_exit(127);
    }
    ::close(pipe_fds[1]);
    out_ = pipe_fds[0];
}

KioskProcess::~KioskProcess() {
    if (pid_ > 0) {
        ::kill(pid_, SIGKILL);
        ::waitpid(pid_, nullptr, 0);
    }
    if (out_ >= 0) ::close(out_);
}

bool KioskProcess::read_some(int timeout_ms) {
    if (out_ < 0) return false;
    pollfd p{out_, POLLIN, 0};
    if (::poll(&p, 1, timeout_ms) <= 0) return true;  // nothing yet, still open
    char buffer[4096];
    const ssize_t n = ::read(out_, buffer, sizeof buffer);
    if (n <= 0) {
        ::close(out_);
        out_ = -1;
        return false;  // the program closed its end: it has ended
    }
    log_.append(buffer, static_cast<std::size_t>(n));
    return true;
}

bool KioskProcess::wait_for_line(const std::string& text, std::chrono::seconds deadline) {
    const auto end = std::chrono::steady_clock::now() + deadline;
    while (std::chrono::steady_clock::now() < end) {
        if (log_.find(text, scanned_) != std::string::npos) {
            scanned_ = log_.find(text, scanned_) + text.size();
            return true;
        }
        if (!read_some(100)) return log_.find(text, scanned_) != std::string::npos;
    }
    return false;
}

void KioskProcess::signal(int signal_number) const {
    if (pid_ > 0) ::kill(pid_, signal_number);
}

int KioskProcess::wait(std::chrono::seconds deadline) {
    const auto end = std::chrono::steady_clock::now() + deadline;
    while (out_ >= 0 && std::chrono::steady_clock::now() < end) read_some(100);
    if (pid_ <= 0) return -1;
    int status = 0;
    while (std::chrono::steady_clock::now() < end) {
        if (::waitpid(pid_, &status, WNOHANG) == pid_) {
            pid_ = -1;
            return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
        }
        ::usleep(20000);
    }
    ::kill(pid_, SIGKILL);
    ::waitpid(pid_, nullptr, 0);
    pid_ = -1;
    return -1;
}

Finished run_kiosk(const std::vector<std::string>& arguments, std::chrono::seconds deadline) {
    KioskProcess process(arguments);
    Finished finished;
    finished.status = process.wait(deadline);
    finished.log = process.log();
    return finished;
}

Image snapshot_after_signal(KioskProcess& kiosk, const std::filesystem::path& file) {
    std::filesystem::remove(file);
    kiosk.signal(SIGUSR1);
    for (int i = 0; i < 200 && !std::filesystem::exists(file); ++i) {
        kiosk.wait_for_line("\n", std::chrono::seconds(1));
    }
    auto image = read_png(file);
    return image ? std::move(image).value() : Image{};
}

Image settled_snapshot(KioskProcess& kiosk, const std::filesystem::path& file) {
    Image last = snapshot_after_signal(kiosk, file);
    for (int i = 0; i < 30 && !last.pixels.empty(); ++i) {
        Image next = snapshot_after_signal(kiosk, file);
        if (next.pixels == last.pixels) return next;
        last = std::move(next);
    }
    return last;
}

}  // namespace gem::kiosk_e2e
