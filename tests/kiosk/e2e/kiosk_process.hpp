#pragma once
// Runs the real gemkiosk program for the end-to-end tests: started with arguments, its stderr
// (the log) read line by line as it comes, waited for with a deadline, stopped by signal.

#include <sys/types.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

#include "picture/image.hpp"

namespace gem::kiosk_e2e {

class KioskProcess {
  public:
    explicit KioskProcess(const std::vector<std::string>& arguments);
    ~KioskProcess();  // kills the program if it still runs
    KioskProcess(const KioskProcess&) = delete;
    KioskProcess& operator=(const KioskProcess&) = delete;

    // Reads the log until a line containing `text` arrives (true) or the deadline passes or
    // the program ends (false).
    bool wait_for_line(const std::string& text, std::chrono::seconds deadline);
    void signal(int signal_number) const;
    // Waits for the program to end (reading the rest of its log); its exit status, or -1 if it
    // had to be killed at the deadline.
    int wait(std::chrono::seconds deadline);
    const std::string& log() const { return log_; }

  private:
    bool read_some(int timeout_ms);
    pid_t pid_ = -1;
    int out_ = -1;
    std::string log_;
    std::size_t scanned_ = 0;
};

// Runs the program to the end; exit status and log.
struct Finished {
    int status = -1;
    std::string log;
};
Finished run_kiosk(const std::vector<std::string>& arguments, std::chrono::seconds deadline);

// Asks the running kiosk for a snapshot (SIGUSR1) into `file` and reads it; an empty image
// when none came within 200 log lines or seconds.
Image snapshot_after_signal(KioskProcess& kiosk, const std::filesystem::path& file);
// Snapshots until two in a row are the same picture: a still view has then all its averaged
// frames, whatever the machine's load (at most 30 tries; the last one otherwise).
Image settled_snapshot(KioskProcess& kiosk, const std::filesystem::path& file);

}  // namespace gem::kiosk_e2e
