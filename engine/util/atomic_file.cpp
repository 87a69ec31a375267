#include "util/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

namespace gem {

Result<AtomicFile> AtomicFile::create(const std::filesystem::path& path) {
    std::filesystem::path temp = path;
    temp += ".tmp-" + std::to_string(::getpid());
    const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0) {
        return Error{"cannot write " + path.string() + ": cannot create " + temp.string() + ": " +
                     std::strerror(errno)};
    }
    return AtomicFile(path, std::move(temp), fd);
}

AtomicFile::AtomicFile(AtomicFile&& other) noexcept
    : path_(std::move(other.path_)),
      temp_(std::move(other.temp_)),
      fd_(other.fd_),
      size_(other.size_) {
    other.fd_ = -1;
    other.temp_.clear();
}

AtomicFile::~AtomicFile() {
    if (fd_ >= 0) ::close(fd_);
    if (!temp_.empty()) ::unlink(temp_.c_str());
}

Error AtomicFile::fail(const char* step, int err) {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
    if (!temp_.empty()) ::unlink(temp_.c_str());
    temp_.clear();
    return Error{"cannot write " + path_.string() + ": " + step + ": " + std::strerror(err)};
}

Result<bool> AtomicFile::append(const void* data, std::size_t size) {
    if (auto ok = write_at(size_, data, size); !ok) return ok;
    size_ += size;
    return true;
}

Result<bool> AtomicFile::write_at(std::uint64_t offset, const void* data, std::size_t size) {
    if (fd_ < 0) return Error{"cannot write " + path_.string() + ": file already closed"};
    const auto* bytes = static_cast<const std::uint8_t*>(data);
    while (size > 0) {
        const ssize_t n = ::pwrite(fd_, bytes, size, static_cast<off_t>(offset));
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return fail("write", n < 0 ? errno : EIO);
        bytes += n;
        size -= static_cast<std::size_t>(n);
        offset += static_cast<std::uint64_t>(n);
    }
    return true;
}

Result<bool> AtomicFile::commit() {
    if (fd_ < 0) return Error{"cannot write " + path_.string() + ": file already closed"};
    if (::fsync(fd_) != 0) return fail("fsync", errno);
    const int fd = fd_;
    fd_ = -1;
    if (::close(fd) != 0) return fail("close", errno);
    if (::rename(temp_.c_str(), path_.c_str()) != 0) return fail("rename", errno);
    temp_.clear();
    // The rename is durable only once the directory entry is on the disk.
    std::filesystem::path dir = path_.parent_path();
    if (dir.empty()) dir = ".";
    const int dir_fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dir_fd < 0)
        return Error{"cannot write " + path_.string() +
                     ": cannot open its directory to flush it: " + std::strerror(errno)};
    const bool synced = ::fsync(dir_fd) == 0;
    const int err = errno;
    ::close(dir_fd);
    if (!synced)
        return Error{"cannot write " + path_.string() +
                     ": fsync of its directory: " + std::strerror(err)};
    return true;
}

Result<std::filesystem::path> write_file_atomic(const std::filesystem::path& path, const void* data,
                                                std::size_t size) {
    auto file = AtomicFile::create(path);
    if (!file) return Error{file.error()};
    if (auto appended = file.value().append(data, size); !appended) return Error{appended.error()};
    if (auto committed = file.value().commit(); !committed) return Error{committed.error()};
    return path;
}

}  // namespace gem
