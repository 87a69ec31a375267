#pragma once
// Runs a shell command for a test and returns its exit status and everything it printed
// (standard output and error together).

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <string>

namespace gem::kiosk::test {

struct CommandResult {
    int status = -1;  // the exit status, or -1 when it did not exit normally
    std::string output;
};

inline CommandResult run_command(const std::string& command) {
    CommandResult result;
    FILE* pipe = ::popen((command + " 2>&1").c_str(), "r");
    if (pipe == nullptr) return result;
    std::array<char, 4096> buffer;
    std::size_t length = 0;
    while ((length = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0)
        result.output.append(buffer.data(), length);
    const int status = ::pclose(pipe);
    if (status >= 0 && WIFEXITED(status)) result.status = WEXITSTATUS(status);
    return result;
}

// Quotes a path for the shell.
inline std::string shell_quoted(const std::string& text) {
    std::string quoted = "'";
    for (char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return quoted + "'";
}

}  // namespace gem::kiosk::test
