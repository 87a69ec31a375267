#pragma once
// Runs another program (minisign, dpkg-deb) found on the PATH, with this process's terminal
// and environment, and waits for it: its exit status, or fails with a message naming it when
// it cannot be started.

#include <string>
#include <vector>

namespace gem::tables {

// argv[0] is the program's name. Returns its exit status; one that could not run, or was killed,
// prints why (gemtables: ...) and returns 1 or more.
int run_program(const std::vector<std::string>& argv, const std::string& missing_hint = "");

}  // namespace gem::tables
