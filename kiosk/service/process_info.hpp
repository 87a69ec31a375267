#pragma once
// Facts about this process the kiosk reports: how long ago the kernel started it (so "time to
// first frame" includes loading the program and its libraries), and its resident memory.

namespace gem::kiosk {

// Seconds on CLOCK_MONOTONIC, the clock of every time the kiosk keeps.
double monotonic_now_s();
// Seconds since the kernel started this process (/proc/self/stat field 22, starttime, in clock
// ticks since boot, against CLOCK_BOOTTIME; proc(5)); a resolution of one tick (10 ms).
double seconds_since_process_start();
// Resident set size in MiB (VmRSS in /proc/self/status); 0 if unreadable.
double resident_mib();

}  // namespace gem::kiosk
