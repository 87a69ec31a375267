#include "service/device_presence.hpp"

#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

namespace gem::kiosk {

namespace {

bool kernel_has(const struct stat& status) {
    // Not a character device (a test's stand-in file): nothing to ask the kernel about.
    if (!S_ISCHR(status.st_mode)) return true;
    const std::string entry = "/sys/dev/char/" + std::to_string(major(status.st_rdev)) + ":" +
                              std::to_string(minor(status.st_rdev));
    return ::access(entry.c_str(), F_OK) == 0;
}

}  // namespace

bool device_present(int fd) {
    struct stat status {};
    if (::fstat(fd, &status) != 0) return true;
    return kernel_has(status);
}

bool device_present(const std::string& path) {
    struct stat status {};
    if (::stat(path.c_str(), &status) != 0) return false;
    return kernel_has(status);
}

}  // namespace gem::kiosk
