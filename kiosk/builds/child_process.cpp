#include "builds/child_process.hpp"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <thread>

extern char** environ;

namespace gem::kiosk {

namespace {

// How long a stopped child has to end on SIGTERM before it gets SIGKILL.
constexpr auto kGrace = std::chrono::seconds(2);

std::string errno_text(const char* what, int err) {
    return std::string(what) + ": " + std::strerror(err);
}

}  // namespace

Result<std::unique_ptr<ChildProcess>> ChildProcess::start(const std::vector<std::string>& argv) {
    if (argv.empty()) return Error{"no program to start"};
    int pipe_fds[2];
    if (::pipe2(pipe_fds, O_CLOEXEC) != 0) return Error{errno_text("pipe", errno)};
    posix_spawn_file_actions_t actions;
    posix_spawnattr_t attributes;
    posix_spawn_file_actions_init(&actions);
    posix_spawnattr_init(&attributes);
    posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_adddup2(&actions, pipe_fds[1], STDOUT_FILENO);
    posix_spawn_file_actions_adddup2(&actions, pipe_fds[1], STDERR_FILENO);
    // The DRM card, input devices and sockets stay the kiosk's (glibc 2.34).
    posix_spawn_file_actions_addclosefrom_np(&actions, STDERR_FILENO + 1);
    sigset_t none;
    sigemptyset(&none);
    sigset_t defaults;
    sigemptyset(&defaults);
    for (int s : {SIGTERM, SIGINT, SIGHUP, SIGUSR1, SIGPIPE, SIGCHLD}) sigaddset(&defaults, s);
    posix_spawnattr_setsigmask(&attributes, &none);
    posix_spawnattr_setsigdefault(&attributes, &defaults);
    posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);

    std::vector<char*> args;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    pid_t pid = -1;
    const int spawned =
        posix_spawn(&pid, argv[0].c_str(), &actions, &attributes, args.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    posix_spawnattr_destroy(&attributes);
    ::close(pipe_fds[1]);
    if (spawned != 0) {
        ::close(pipe_fds[0]);
        return Error{"cannot start " + argv[0] + ": " + std::strerror(spawned)};
    }
    const int flags = ::fcntl(pipe_fds[0], F_GETFL);
    ::fcntl(pipe_fds[0], F_SETFL, flags | O_NONBLOCK);
    return std::unique_ptr<ChildProcess>(new ChildProcess(pid, pipe_fds[0]));
}

ChildProcess::~ChildProcess() {
    if (fd_ >= 0) ::close(fd_);
    if (status_ || pid_ < 0) return;
    ::kill(pid_, SIGTERM);
    const auto give_up = std::chrono::steady_clock::now() + kGrace;
    int status = 0;
    while (::waitpid(pid_, &status, WNOHANG) == 0) {
        if (std::chrono::steady_clock::now() > give_up) {
            ::kill(pid_, SIGKILL);
            ::waitpid(pid_, &status, 0);
            return;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
}

std::vector<std::string> ChildProcess::read_lines() {
    std::vector<std::string> lines;
    if (fd_ < 0) return lines;
    char buffer[4096];
    bool closed = false;
    for (;;) {
        const ssize_t n = ::read(fd_, buffer, sizeof buffer);
        if (n > 0) {
            partial_.append(buffer, static_cast<std::size_t>(n));
            continue;
        }
        if (n == 0) closed = true;
        if (n < 0 && errno == EINTR) continue;
        break;  // EAGAIN: nothing more for now; another error: treated as the end
    }
    std::size_t start = 0;
    for (std::size_t nl; (nl = partial_.find('\n', start)) != std::string::npos; start = nl + 1) {
        std::string line = partial_.substr(start, nl - start);
        // A progress bar's carriage returns: the last state of the line is what it says.
        if (const auto cr = line.rfind('\r'); cr != std::string::npos) line.erase(0, cr + 1);
        if (!line.empty()) lines.push_back(std::move(line));
    }
    partial_.erase(0, start);
    if (closed) {
        if (!partial_.empty()) lines.push_back(std::move(partial_));
        partial_.clear();
        ::close(fd_);
        fd_ = -1;
        reap();
    }
    return lines;
}

void ChildProcess::reap() {
    // Its output has ended, so it is exiting: the wait is short.
    int status = 0;
    while (::waitpid(pid_, &status, 0) < 0) {
        if (errno != EINTR) {
            status_ = -1;
            return;
        }
    }
    status_ = status;
}

bool ChildProcess::succeeded() const {
    return status_ && *status_ != -1 && WIFEXITED(*status_) && WEXITSTATUS(*status_) == 0;
}

std::string ChildProcess::describe_end() const {
    if (!status_) return {};
    if (*status_ == -1) return "could not be waited for";
    if (WIFEXITED(*status_)) return "exited with status " + std::to_string(WEXITSTATUS(*status_));
    if (WIFSIGNALED(*status_)) {
        return "was killed by signal " + std::to_string(WTERMSIG(*status_)) + " (" +
               strsignal(WTERMSIG(*status_)) + ")";
    }
    return "ended";
}

}  // namespace gem::kiosk
