#include "delivery/catalogue_files.hpp"

#include <fcntl.h>
#include <sodium.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <system_error>

#include "util/atomic_file.hpp"

namespace gem::tables {

namespace fs = std::filesystem;

namespace {

constexpr const char* kDigestComment =
    "# Every other file of the catalogue and its digest (written by gemtables).";

}  // namespace

std::string toml_string(const std::string& text) {
    std::string out = "\"";
    for (const char c : text) {
        if (c == '"' || c == '\\') out += '\\';
        out += c;
    }
    return out + "\"";
}

bool is_catalogue_file_name(const std::string& name) {
    if (name.empty() || name.front() == '/') return false;
    for (const auto& part : fs::path(name)) {
        if (part == ".." || part == ".") return false;
    }
    return name.find('\0') == std::string::npos && name.find('\\') == std::string::npos;
}

Result<std::vector<std::string>> catalogue_payload(const fs::path& dir) {
    std::vector<std::string> files;
    std::error_code ec;
    fs::recursive_directory_iterator it(dir, ec);
    if (ec) return Error{dir.string() + ": " + ec.message()};
    for (; it != fs::recursive_directory_iterator(); it.increment(ec)) {
        if (ec) break;
        const fs::file_status status = it->symlink_status(ec);
        if (ec) return Error{it->path().string() + ": " + ec.message()};
        const std::string name = it->path().lexically_relative(dir).generic_string();
        if (fs::is_directory(status)) continue;
        if (!fs::is_regular_file(status)) {
            return Error{name + ": not a regular file (a catalogue holds plain files only)"};
        }
        if (name == kManifestName || name == kSignatureName) continue;
        files.push_back(name);
    }
    if (ec) return Error{dir.string() + ": " + ec.message()};
    std::sort(files.begin(), files.end());
    return files;
}

Result<std::string> file_digest(const fs::path& path) {
    if (sodium_init() < 0) return Error{"libsodium cannot start"};
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return Error{path.string() + ": " + std::strerror(errno)};
    ::posix_fadvise(fd, 0, 0, POSIX_FADV_SEQUENTIAL);
    crypto_generichash_state state;
    crypto_generichash_init(&state, nullptr, 0, kDigestBytes);
    std::vector<unsigned char> buffer(1 << 20);
    for (;;) {
        const ssize_t got = ::read(fd, buffer.data(), buffer.size());
        if (got < 0 && errno == EINTR) continue;
        if (got < 0) {
            const int err = errno;
            ::close(fd);
            return Error{path.string() + ": " + std::strerror(err)};
        }
        if (got == 0) break;
        crypto_generichash_update(&state, buffer.data(), static_cast<unsigned long long>(got));
    }
    ::close(fd);
    unsigned char digest[kDigestBytes];
    crypto_generichash_final(&state, digest, sizeof digest);
    char text[2 * kDigestBytes + 1];
    return std::string(sodium_bin2hex(text, sizeof text, digest, sizeof digest));
}

Result<std::string> digest_table(const fs::path& dir) {
    Result<std::vector<std::string>> files = catalogue_payload(dir);
    if (!files) return Error{files.error()};
    std::string table = std::string(kDigestTable) + "\n";
    for (const std::string& name : files.value()) {
        Result<std::string> digest = file_digest(dir / name);
        if (!digest) return Error{digest.error()};
        table += toml_string(name) + " = \"" + digest.value() + "\"\n";
    }
    return table;
}

Result<std::size_t> write_digests(const fs::path& dir) {
    const fs::path manifest = dir / kManifestName;
    std::ifstream in(manifest, std::ios::binary);
    if (!in) return Error{manifest.string() + ": cannot read"};
    std::stringstream whole;
    whole << in.rdbuf();
    std::string text = whole.str();
    // The old table runs from its header line to the end of the file.
    std::size_t start = std::string::npos;
    std::size_t line_start = 0;
    while (line_start < text.size()) {
        std::size_t end = text.find('\n', line_start);
        if (end == std::string::npos) end = text.size();
        std::string line = text.substr(line_start, end - line_start);
        line.erase(0, line.find_first_not_of(" \t"));
        if (start == std::string::npos && line.rfind(kDigestTable, 0) == 0) {
            start = line_start;
        } else if (start != std::string::npos && line.rfind('[', 0) == 0) {
            return Error{manifest.string() + ": the " + kDigestTable +
                         " table must be the last one (a table follows it)"};
        }
        line_start = end + 1;
    }
    if (start != std::string::npos) {
        // With the comment this function writes above it.
        const std::size_t comment = text.rfind(kDigestComment, start);
        if (comment != std::string::npos && comment + std::strlen(kDigestComment) + 1 == start) {
            start = comment;
        }
        text.erase(start);
    }
    if (!text.empty() && text.back() != '\n') text += '\n';
    Result<std::string> table = digest_table(dir);
    if (!table) return Error{table.error()};
    text += "\n" + std::string(kDigestComment) + "\n" + table.value();
    // Blank lines that an old table's removal left are folded into the one written here.
    while (text.find("\n\n\n") != std::string::npos) text.erase(text.find("\n\n\n"), 1);
    auto written = write_file_atomic(manifest, text.data(), text.size());
    if (!written) return Error{written.error()};
    return static_cast<std::size_t>(std::count(table.value().begin(), table.value().end(), '\n') -
                                    1);
}

Result<bool> check_catalogue_digests(const fs::path& dir,
                                     const std::map<std::string, std::string>& digests) {
    Result<std::vector<std::string>> files = catalogue_payload(dir);
    if (!files) return Error{files.error()};
    for (const std::string& name : files.value()) {
        if (digests.count(name) == 0) {
            return Error{name +
                         ": not named in the manifest's [blake2b] table (added after "
                         "signing, or left over from an interrupted installation)"};
        }
    }
    for (const auto& [name, expected] : digests) {
        if (!std::binary_search(files.value().begin(), files.value().end(), name)) {
            return Error{name + ": missing (the manifest's [blake2b] table names it)"};
        }
        Result<std::string> digest = file_digest(dir / name);
        if (!digest) {
            // Staff know the catalogue's own names: the error without the absolute path.
            const std::string absolute = (dir / name).string() + ": ";
            const std::string& why = digest.error();
            return Error{name + ": " +
                         (why.rfind(absolute, 0) == 0 ? why.substr(absolute.size()) : why)};
        }
        if (digest.value() != expected) {
            return Error{name +
                         ": does not match its digest in the manifest (changed or "
                         "damaged since the catalogue was made)"};
        }
    }
    return true;
}

}  // namespace gem::tables
