#include "app/snapshot.hpp"

#include <unistd.h>

#include <system_error>

#include "picture/image.hpp"

namespace gem::kiosk {

Result<bool> write_snapshot(const gpu::RenderTarget& picture, const std::filesystem::path& file) {
    std::error_code ec;
    if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path(), ec);
    if (ec)
        return Error{"snapshot: cannot create " + file.parent_path().string() + ": " +
                     ec.message()};
    // The temporary name is unique per process, so two kiosks never write the same one.
    std::filesystem::path temporary = file;
    temporary += ".tmp-" + std::to_string(::getpid());
    auto written = write_png(picture.read(), temporary);
    if (!written) {
        std::filesystem::remove(temporary, ec);
        return Error{"snapshot: " + written.error()};
    }
    std::filesystem::rename(temporary, file, ec);
    if (ec) {
        std::filesystem::remove(temporary, ec);
        return Error{"snapshot: cannot rename onto " + file.string() + ": " + ec.message()};
    }
    return true;
}

}  // namespace gem::kiosk
