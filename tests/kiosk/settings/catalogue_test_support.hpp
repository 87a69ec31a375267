#pragma once
// Shared pieces of the catalogue tests: a tiny real database traced once per run, catalogue
// directories written by hand, the .gemdb layout facts needed to damage a payload (written out
// from docs/gemdb-format.md, not taken from the reader), stderr capture and waiting.

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace gem::kiosk::catalogue_test {

// A fresh, empty directory under the test artifacts.
std::filesystem::path fresh_dir(const std::string& name);

// A round brilliant traced at one 32 px level with wide view spacing: a real database in well
// under a second. Built on first use, then shared.
const std::filesystem::path& tiny_database();

std::vector<std::uint8_t> read_bytes(const std::filesystem::path& path);
void write_bytes(const std::filesystem::path& path, const std::vector<std::uint8_t>& bytes);
void write_text(const std::filesystem::path& path, const std::string& text);
std::string read_text(const std::filesystem::path& path);
// The shipped halo (config/pieces/halo.toml) at dir/pieces/halo.toml and the stone files it
// names at dir/stones/, laid out as in config/ so that its "../stones/x.toml" resolve; its text,
// for variants of it.
std::string copy_shipped_halo(const std::filesystem::path& dir);
// Runs a shell command; its stdout and stderr together, and its exit status in `status`.
std::string run_command(const std::string& command, int* status = nullptr);

// A catalogue named `name` with one stone "Round" whose database is a copy of tiny_database()
// at stones/round.gemdb (the manifest is written first, then the database).
void write_catalogue(const std::filesystem::path& dir, const std::string& name);
std::string one_stone_manifest(const std::string& name);

// Where view `view` level `level`'s compressed payload lies, read from the index section by
// hand: the header's section table holds (id, reserved, offset, bytes, checksum) records of
// 32 bytes from byte 48; the index section (id 6) holds 32-byte records of (offset u64,
// compressed u32, raw u32, checksum u64, hits u32, rays u32), view-major. Little-endian.
struct PayloadSpan {
    std::uint64_t offset = 0;
    std::uint32_t bytes = 0;
};
PayloadSpan payload_span(const std::vector<std::uint8_t>& file, std::uint32_t view,
                         std::uint32_t level, std::uint32_t levels);
std::uint32_t header_view_count(const std::vector<std::uint8_t>& file);

// Redirects fd 2 into a file while alive; text() is what was written so far.
class StderrCapture {
  public:
    StderrCapture();
    ~StderrCapture();
    std::string text() const;

  private:
    std::filesystem::path path_;
    int saved_ = -1;
};

// Polls `done` every 10 ms for up to 60 s (a loaded build machine), and says whether it held.
bool wait_until(const std::function<bool()>& done);

}  // namespace gem::kiosk::catalogue_test
