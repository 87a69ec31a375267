#pragma once
// Whether a device node still stands for a device the kernel has: unplugging removes the
// kernel's device (its /sys/dev/char entry) first and udev removes the node in /dev after,
// so for a moment a node exists for a device that does not. Errors about such a device are
// the unplugging's, not faults.

#include <string>

namespace gem::kiosk {

bool device_present(int fd);                   // the device behind an open descriptor
bool device_present(const std::string& path);  // the device behind a node

}  // namespace gem::kiosk
