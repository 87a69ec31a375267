#pragma once
// A program the kiosk runs beside its frames (the table builder, design_tables.hpp): started
// with posix_spawn, its standard output and error in one non-blocking pipe the main loop polls,
// its output read a line at a time, and its end told as one phrase. Dropped while it runs, it
// is stopped (SIGTERM, then SIGKILL after a grace period) and reaped: no process outlives the
// kiosk's interest in it.

#include <sys/types.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "util/result.hpp"

namespace gem::kiosk {

class ChildProcess {
  public:
    // argv[0] is the program's path. The child gets no descriptor of the kiosk's but the
    // pipe, an empty signal mask and default signal actions (the kiosk blocks its signals
    // for signalfd, and a child would inherit that).
    static Result<std::unique_ptr<ChildProcess>> start(const std::vector<std::string>& argv);
    ~ChildProcess();
    ChildProcess(const ChildProcess&) = delete;
    ChildProcess& operator=(const ChildProcess&) = delete;

    pid_t pid() const { return pid_; }
    // Readable when output arrives or the child closes its end; -1 once it has ended.
    int fd() const { return fd_; }
    // Reads what has arrived and returns its complete lines; reaps the child once its output
    // ends.
    std::vector<std::string> read_lines();
    bool ended() const { return status_.has_value(); }
    bool succeeded() const;
    // "exited with status 3", "was killed by signal 9 (Killed)"; empty while it runs.
    std::string describe_end() const;

  private:
    ChildProcess(pid_t pid, int fd) : pid_(pid), fd_(fd) {}
    void reap();

    pid_t pid_ = -1;
    int fd_ = -1;
    std::string partial_;  // output after the last newline
    std::optional<int> status_;
};

}  // namespace gem::kiosk
