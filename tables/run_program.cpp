#include "run_program.hpp"

#include <spawn.h>
#include <sys/wait.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "commands.hpp"

extern char** environ;

namespace gem::tables {

int run_program(const std::vector<std::string>& args, const std::string& missing_hint) {
    std::vector<char*> argv;
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    std::fflush(stdout);  // what this process printed comes before the child's lines
    pid_t pid = 0;
    const int spawned = posix_spawnp(&pid, argv[0], nullptr, nullptr, argv.data(), environ);
    if (spawned != 0) {
        return fail("cannot run " + args[0] + " (" + std::strerror(spawned) + ")" +
                    (missing_hint.empty() ? "" : ": " + missing_hint));
    }
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    if (!WIFEXITED(status)) return fail(args[0] + " was killed");
    return WEXITSTATUS(status);
}

}  // namespace gem::tables
