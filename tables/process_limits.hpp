#pragma once
// What a build running beside a live display asks of the system: the CPU only when nothing
// else wants it, and a bound on its memory. The kiosk builds a design's tables with
// `gemtables build --idle --memory-mb N` (kiosk/builds/design_tables.hpp) while it draws frames.

#include <cstdint>
#include <string>

#include "util/result.hpp"

namespace gem::tables {

// SCHED_IDLE for the process (threads made afterwards inherit it) and nice 19 as well, for a
// kernel or sandbox that refuses SCHED_IDLE. Each is tried, not assumed; the line says what
// the process runs at afterwards, read back from the kernel, and what was refused.
std::string run_at_idle_priority();

// An address-space limit of `megabytes` (RLIMIT_AS), and a new-handler that ends the process
// with one line naming the limit when an allocation on any thread fails under it. The value is
// a line to print when the limit was deliberately not applied (a sanitizer build), else empty.
Result<std::string> limit_memory(std::uint64_t megabytes);

}  // namespace gem::tables
