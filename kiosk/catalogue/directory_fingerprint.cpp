#include "catalogue/directory_fingerprint.hpp"

#include <sys/stat.h>
#include <xxhash.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <string>
#include <system_error>

namespace gem::kiosk {

namespace {

struct Entry {
    std::string name;  // relative to the root
    std::uint32_t mode = 0;
    std::int64_t size = 0;
    std::int64_t mtime_ns = 0;
    std::int64_t ctime_ns = 0;
};

}  // namespace

Result<DirectoryFingerprint> fingerprint_directory(const std::filesystem::path& dir) {
    DirectoryFingerprint result;
    std::vector<Entry> entries;
    std::error_code ec;
    std::filesystem::recursive_directory_iterator it(dir, ec);
    if (ec) return Error{dir.string() + ": " + ec.message()};
    result.directories.push_back(dir);
    for (; it != std::filesystem::recursive_directory_iterator(); it.increment(ec)) {
        if (ec) break;
        const std::filesystem::path& path = it->path();
        struct stat st {};
        // An entry removed between listing and stat is a change like any other.
        if (::lstat(path.c_str(), &st) != 0) {
            if (errno == ENOENT) continue;
            return Error{path.string() + ": " + std::strerror(errno)};
        }
        Entry e;
        e.name = path.lexically_relative(dir).string();
        e.mode = st.st_mode;
        e.size = st.st_size;
        e.mtime_ns =
            static_cast<std::int64_t>(st.st_mtim.tv_sec) * 1'000'000'000 + st.st_mtim.tv_nsec;
        e.ctime_ns =
            static_cast<std::int64_t>(st.st_ctim.tv_sec) * 1'000'000'000 + st.st_ctim.tv_nsec;
        if (S_ISDIR(st.st_mode)) result.directories.push_back(path);
        if (S_ISREG(st.st_mode)) {
            const std::string ext = path.extension().string();
            if (ext == ".dpkg-new" || ext == ".dpkg-tmp") result.unpacking = true;
            ++result.files;
            result.bytes += static_cast<std::uint64_t>(st.st_size);
        }
        entries.push_back(std::move(e));
    }
    if (ec) return Error{dir.string() + ": " + ec.message()};
    // Directory order is the file system's; sorting makes the hash depend on the tree only.
    std::sort(entries.begin(), entries.end(),
              [](const Entry& a, const Entry& b) { return a.name < b.name; });
    XXH64_state_t* state = XXH64_createState();
    XXH64_reset(state, 0);
    for (const Entry& e : entries) {
        XXH64_update(state, e.name.data(), e.name.size() + 1);  // with its NUL as separator
        XXH64_update(state, &e.mode, sizeof e.mode);
        XXH64_update(state, &e.size, sizeof e.size);
        XXH64_update(state, &e.mtime_ns, sizeof e.mtime_ns);
        XXH64_update(state, &e.ctime_ns, sizeof e.ctime_ns);
    }
    result.hash = XXH64_digest(state);
    XXH64_freeState(state);
    return result;
}

}  // namespace gem::kiosk
