#include "catalogue/payload_checksums.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <xxhash.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <memory>
#include <vector>

namespace gem::kiosk {

namespace {

struct FreeState {
    void operator()(XXH64_state_t* s) const { XXH64_freeState(s); }
};

}  // namespace

std::optional<std::string> find_damaged_payload(const Database& database) {
    // pread(2), not a memory map: the source may be on a stick that is pulled, or a file staff
    // overwrite (cp truncates first); reading a mapped page past a file's new end raises SIGBUS
    // (mmap(2)), where read just returns short.
    const int fd = ::open(database.path().c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return std::string("cannot open: ") + std::strerror(errno);
    ::posix_fadvise(fd, 0, 0, POSIX_FADV_SEQUENTIAL);
    std::vector<std::uint8_t> buffer(1 << 20);
    const std::unique_ptr<XXH64_state_t, FreeState> state(XXH64_createState());
    std::optional<std::string> damaged;
    for (std::uint32_t v = 0; v < database.view_count() && !damaged; ++v) {
        for (std::uint32_t l = 0; l < database.level_count() && !damaged; ++l) {
            const PayloadInfo& p = database.payload(v, l);
            const std::string where = "view " + std::to_string(v) + " level " + std::to_string(l);
            XXH64_reset(state.get(), 0);
            std::uint64_t done = 0;
            while (done < p.compressed_bytes) {
                const std::size_t want =
                    std::min<std::uint64_t>(buffer.size(), p.compressed_bytes - done);
                const ssize_t got =
                    ::pread(fd, buffer.data(), want, static_cast<off_t>(p.offset + done));
                if (got < 0 && errno == EINTR) continue;
                if (got <= 0) {
                    damaged = where + ": " +
                              (got < 0 ? std::string(std::strerror(errno))
                                       : std::string("the file ended early (changed while read)"));
                    break;
                }
                XXH64_update(state.get(), buffer.data(), static_cast<std::size_t>(got));
                done += static_cast<std::uint64_t>(got);
            }
            if (!damaged && XXH64_digest(state.get()) != p.checksum) {
                damaged = where + ": checksum mismatch";
            }
        }
    }
    ::close(fd);
    return damaged;
}

Result<std::shared_ptr<const Database>> open_intact_database(const std::filesystem::path& path) {
    Result<Database> opened = Database::open(path);
    if (!opened) return Error{opened.error()};
    if (auto damaged = find_damaged_payload(opened.value())) {
        return Error{path.string() + ": " + *damaged};
    }
    return std::make_shared<const Database>(std::move(opened).value());
}

}  // namespace gem::kiosk
