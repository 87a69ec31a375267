#include "catalogue/catalogue_store.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <system_error>

#include "catalogue/validate.hpp"
#include "service/log.hpp"
#include "util/atomic_file.hpp"

namespace gem::kiosk {

namespace fs = std::filesystem;

namespace {

constexpr const char* kTempPrefix = ".tmp-";
constexpr std::size_t kRememberedSources = 256;

fs::path catalogues_dir(const fs::path& state) {
    return state / "catalogues";
}

Error fault(const fs::path& path, int err) {
    return Error{path.string() + ": " + std::strerror(err)};
}

// The manifest's name as a directory name: whatever a staff member typed stays readable, but
// cannot make a path ("../x") or a hidden entry.
std::string directory_name(const std::string& name) {
    std::string out;
    for (const char c : name) {
        const bool plain = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
                           (c >= '0' && c <= '9') || c == '-' || c == '_' || c == '.';
        out += plain ? c : '_';
        if (out.size() == 64) break;
    }
    while (!out.empty() && out.front() == '.') out.erase(out.begin());
    return out.empty() ? "catalogue" : out;
}

// One more than the largest n of any "<name>-<n>" under `dir`, so names never repeat.
unsigned next_number(const fs::path& dir) {
    unsigned largest = 0;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(dir, ec)) {
        const std::string name = entry.path().filename().string();
        const std::size_t dash = name.rfind('-');
        if (dash == std::string::npos || dash + 1 == name.size()) continue;
        const std::string digits = name.substr(dash + 1);
        if (!std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; }))
            continue;
        if (digits.size() < 10)
            largest = std::max(largest, static_cast<unsigned>(std::stoul(digits)));
    }
    return largest + 1;
}

// Makes a file's data or a directory's entries durable (fsync(2); for a directory this is what
// makes a rename or a new entry in it survive a power cut).
Result<bool> sync_path(const fs::path& path, bool directory) {
    const int fd = ::open(path.c_str(), (directory ? O_DIRECTORY : 0) | O_RDONLY | O_CLOEXEC);
    if (fd < 0) return fault(path, errno);
    const int rc = ::fsync(fd);
    const int err = errno;
    ::close(fd);
    if (rc != 0) return fault(path, err);
    return true;
}

Result<bool> copy_file(const fs::path& from, const fs::path& to, std::stop_token stop) {
    const int in = ::open(from.c_str(), O_RDONLY | O_CLOEXEC);
    if (in < 0) return fault(from, errno);
    const int out = ::open(to.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
    if (out < 0) {
        const int err = errno;
        ::close(in);
        return fault(to, err);
    }
    std::vector<char> buffer(1 << 20);
    Result<bool> result = true;
    for (;;) {
        if (stop.stop_requested()) {
            result = Error{from.string() + ": copy stopped (shutting down)"};
            break;
        }
        const ssize_t got = ::read(in, buffer.data(), buffer.size());
        if (got < 0 && errno == EINTR) continue;
        if (got < 0) {
            result = fault(from, errno);
            break;
        }
        if (got == 0) break;
        ssize_t done = 0;
        while (done < got) {
            const ssize_t put =
                ::write(out, buffer.data() + done, static_cast<std::size_t>(got - done));
            if (put < 0 && errno == EINTR) continue;
            if (put < 0) {
                result = fault(to, errno);  // ENOSPC, EFBIG, EDQUOT, EIO
                break;
            }
            done += put;
        }
        if (!result) break;
    }
    // Write-back errors (a full disk on some file systems) are reported by fsync or close.
    if (result && ::fsync(out) != 0) result = fault(to, errno);
    if (::close(out) != 0 && result) result = fault(to, errno);
    ::close(in);
    return result;
}

Result<bool> copy_tree(const fs::path& source, const fs::path& target, std::stop_token stop) {
    std::error_code ec;
    if (!fs::create_directory(target, ec)) return Error{target.string() + ": " + ec.message()};
    std::vector<fs::path> directories{target};
    fs::recursive_directory_iterator it(source, ec);
    if (ec) return Error{source.string() + ": " + ec.message()};
    for (; it != fs::recursive_directory_iterator(); it.increment(ec)) {
        if (ec) break;
        const fs::path to = target / it->path().lexically_relative(source);
        const fs::file_status status = it->symlink_status(ec);
        if (ec) return Error{it->path().string() + ": " + ec.message()};
        if (fs::is_directory(status)) {
            if (!fs::create_directory(to, ec)) return Error{to.string() + ": " + ec.message()};
            directories.push_back(to);
        } else if (fs::is_regular_file(status)) {
            if (auto copied = copy_file(it->path(), to, stop); !copied) return copied;
        } else {
            // A symlink could point anywhere (outside a USB stick); only plain files are copied.
            return Error{it->path().string() + ": not a regular file or directory"};
        }
    }
    if (ec) return Error{source.string() + ": " + ec.message()};
    for (const fs::path& dir : directories) {
        if (auto synced = sync_path(dir, true); !synced) return synced;
    }
    return true;
}

}  // namespace

Result<fs::path> copy_catalogue(const fs::path& source, const fs::path& state_dir,
                                const std::string& name, std::stop_token stop) {
    const fs::path parent = catalogues_dir(state_dir);
    std::error_code ec;
    fs::create_directories(parent, ec);
    if (ec) return Error{parent.string() + ": " + ec.message()};
    const std::string final_name = directory_name(name) + "-" + std::to_string(next_number(parent));
    const fs::path temp = parent / (kTempPrefix + final_name);
    const fs::path final_path = parent / final_name;
    fs::remove_all(temp, ec);
    Result<bool> copied = copy_tree(source, temp, stop);
    if (copied && ::rename(temp.c_str(), final_path.c_str()) != 0)
        copied = fault(final_path, errno);
    if (copied) copied = sync_path(parent, true);
    if (!copied) {
        fs::remove_all(temp, ec);
        fs::remove_all(final_path, ec);
        return Error{copied.error()};
    }
    return final_path;
}

Result<bool> make_current(const fs::path& state_dir, const fs::path& copy) {
    const fs::path link = state_dir / "current";
    const fs::path temp = state_dir / ".current.tmp";
    // Relative, so that the state directory can be moved or mounted elsewhere.
    const fs::path target = copy.lexically_relative(state_dir);
    if (target.empty() || *target.begin() == "..") {
        return Error{copy.string() + ": not inside " + state_dir.string()};
    }
    ::unlink(temp.c_str());
    if (::symlink(target.c_str(), temp.c_str()) != 0) return fault(temp, errno);
    if (::rename(temp.c_str(), link.c_str()) != 0) {
        const int err = errno;
        ::unlink(temp.c_str());
        return fault(link, err);
    }
    return sync_path(state_dir, true);
}

fs::path current_copy(const fs::path& state_dir) {
    std::error_code ec;
    fs::path resolved = fs::canonical(state_dir / "current", ec);
    return ec ? fs::path() : resolved;
}

void prune_copies(const fs::path& state_dir, const std::vector<fs::path>& keep) {
    std::error_code ec;
    std::vector<fs::path> doomed;
    for (const auto& entry : fs::directory_iterator(catalogues_dir(state_dir), ec)) {
        std::error_code entry_ec;
        const fs::path real = fs::canonical(entry.path(), entry_ec);
        const bool kept = !entry_ec && std::find(keep.begin(), keep.end(), real) != keep.end();
        if (!kept) doomed.push_back(entry.path());
    }
    for (const fs::path& path : doomed) {
        fs::remove_all(path, ec);
        if (ec) log_warning("cannot remove old catalogue " + path.string() + ": " + ec.message());
    }
}

void remove_partial_copies(const fs::path& state_dir) {
    std::error_code ec;
    std::vector<fs::path> doomed;
    for (const auto& entry : fs::directory_iterator(catalogues_dir(state_dir), ec)) {
        if (entry.path().filename().string().rfind(kTempPrefix, 0) == 0) {
            doomed.push_back(entry.path());
        }
    }
    for (const fs::path& path : doomed) fs::remove_all(path, ec);
}

std::vector<std::uint64_t> read_sources(const fs::path& state_dir, const char* list) {
    std::vector<std::uint64_t> out;
    std::ifstream in(state_dir / list);
    std::string line;
    while (std::getline(in, line)) {
        try {
            out.push_back(std::stoull(line, nullptr, 16));
        } catch (const std::exception&) {
            // A damaged line only means a source may be installed once more.
        }
    }
    return out;
}

Result<bool> remember_source(const fs::path& state_dir, const char* list,
                             std::uint64_t fingerprint) {
    std::vector<std::uint64_t> known = read_sources(state_dir, list);
    known.push_back(fingerprint);
    if (known.size() > kRememberedSources)
        known.erase(known.begin(), known.end() - kRememberedSources);
    std::string text;
    for (const std::uint64_t f : known) {
        char line[24];
        std::snprintf(line, sizeof line, "%016llx\n", static_cast<unsigned long long>(f));
        text += line;
    }
    auto written = write_file_atomic(state_dir / list, text.data(), text.size());
    if (!written) return Error{written.error()};
    return true;
}

Result<fs::path> set_aside_rejected(const fs::path& source, const std::string& reason) {
    std::error_code ec;
    const fs::path parent = source.parent_path();
    const std::string name = source.filename().string();
    fs::path target = parent / (name + kRejectedSuffix);
    for (int n = 2; fs::exists(fs::symlink_status(target, ec)) ||
                    fs::exists(fs::symlink_status(fs::path(target.string() + ".txt"), ec));
         ++n) {
        target = parent / (name + "-" + std::to_string(n) + kRejectedSuffix);
    }
    if (::rename(source.c_str(), target.c_str()) != 0) return fault(target, errno);
    const std::string text = "gemkiosk refused the catalogue " + name + ":\n" + reason +
                             "\n\nMend it and copy it into the inbox again; the folder " +
                             target.filename().string() + " and this note may be deleted.\n";
    const fs::path note(target.string() + ".txt");
    auto written = write_file_atomic(note, text.data(), text.size());
    if (!written) log_warning("cannot write why " + name + " was refused: " + written.error());
    // The kiosk's umask keeps its own files private; this one is for staff to read.
    fs::permissions(note, fs::perms(0644), ec);
    if (auto synced = sync_path(parent, true); !synced) log_warning(synced.error());
    return target;
}

Result<Catalogue> load_startup_catalogue(const CatalogueOptions& options, Entries entries,
                                         std::stop_token stop) {
    const fs::path current = options.state_dir / "current";
    std::error_code ec;
    std::string why_not_current = current.string() + ": none installed";
    if (fs::exists(fs::symlink_status(current, ec))) {
        Result<Catalogue> installed =
            validate_catalogue(current, options.trust, stop, DigestCheck::skip, entries);
        if (installed) return installed;
        why_not_current = installed.error();
        log_warning(why_not_current + " (" + current.string() + "); using the default catalogue");
    }
    // The shipped catalogue is part of the kiosk's own installation, not a delivery: its
    // digests are checked where it has them, but no chain signs it.
    Result<Catalogue> shipped =
        validate_catalogue(options.default_catalogue, {}, stop, DigestCheck::check, entries);
    if (shipped) return shipped;
    return Error{"no catalogue to show: " + why_not_current + "; default " +
                 options.default_catalogue.string() + ": " + shipped.error()};
}

}  // namespace gem::kiosk
