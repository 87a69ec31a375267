#pragma once
// gemkiosk --check-config FILE: the config as the kiosk would read it at start, every problem
// on its own line, as `nginx -t` and `sshd -t` check theirs before a restart. A problem is a
// line the kiosk would log as an error: a file that does not read or parse, a bad value or
// unknown key, a trusted key file that cannot be read or is not a minisign public key. The
// systemd unit runs it before each start (ExecStartPre=-), so the journal says what is wrong
// just before the kiosk falls back (settings/config_fallback.hpp).

#include <filesystem>
#include <ostream>

namespace gem::kiosk {

// Writes each problem and a last line saying how many there were; the count.
int check_config(const std::filesystem::path& file, std::ostream& out);

}  // namespace gem::kiosk
