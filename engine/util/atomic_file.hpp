#pragma once
// A file that appears under its name only when complete: written as `<name>.tmp-<pid>`,
// flushed to the disk, renamed over the name and the directory flushed, so a crash leaves
// either the old file or the whole new one. Dropped without commit(), the temporary is removed.

#include <cstddef>
#include <cstdint>
#include <filesystem>

#include "util/result.hpp"

namespace gem {

class AtomicFile {
  public:
    static Result<AtomicFile> create(const std::filesystem::path& path);
    AtomicFile(AtomicFile&& other) noexcept;
    AtomicFile& operator=(AtomicFile&&) = delete;
    ~AtomicFile();

    Result<bool> append(const void* data, std::size_t size);
    Result<bool> write_at(std::uint64_t offset, const void* data, std::size_t size);
    Result<bool> commit();
    std::uint64_t size() const { return size_; }

  private:
    AtomicFile(std::filesystem::path path, std::filesystem::path temp, int fd)
        : path_(std::move(path)), temp_(std::move(temp)), fd_(fd) {}
    Error fail(const char* step, int err);

    std::filesystem::path path_;
    std::filesystem::path temp_;
    int fd_ = -1;
    std::uint64_t size_ = 0;
};

// The whole of `data` as one atomic file; returns the path written.
Result<std::filesystem::path> write_file_atomic(const std::filesystem::path& path, const void* data,
                                                std::size_t size);

}  // namespace gem
