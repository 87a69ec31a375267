#include "render/file_write.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>
#include <system_error>

namespace gem {

namespace {

Error write_error(const std::filesystem::path& path, int err) {
    return Error{"cannot write " + path.string() + ": " + std::strerror(err)};
}

}  // namespace

Result<std::filesystem::path> write_file_atomic(const std::filesystem::path& path, const void* data,
                                                std::size_t size) {
    std::filesystem::path temp = path;
    temp += ".part";
    std::FILE* file = std::fopen(temp.c_str(), "wb");
    if (file == nullptr) return write_error(path, errno);
    const bool written = std::fwrite(data, 1, size, file) == size;
    int err = errno;
    const bool flushed = std::fflush(file) == 0;
    if (written && !flushed) err = errno;
    const bool closed = std::fclose(file) == 0;
    if (written && flushed && !closed) err = errno;
    if (!written || !flushed || !closed) {
        std::remove(temp.c_str());
        return write_error(path, err != 0 ? err : EIO);
    }
    std::error_code ec;
    std::filesystem::rename(temp, path, ec);
    if (ec) {
        std::remove(temp.c_str());
        return Error{"cannot write " + path.string() + ": " + ec.message()};
    }
    return path;
}

}  // namespace gem
