#include <cstdio>

#include "commands.hpp"

namespace gem::tables {

int fail(const std::string& message) {
    std::fprintf(stderr, "gemtables: %s\n", message.c_str());
    return 1;
}

}  // namespace gem::tables
