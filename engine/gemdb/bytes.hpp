#pragma once
// Little-endian byte packing for the .gemdb format. The writer appends; the reader reads
// through a bounds-checked cursor that never reads past its span and remembers the first
// failure, so parsers check once at the end instead of after every field.

#include <cstdint>
#include <cstring>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace gem {

class ByteWriter {
  public:
    void u8(std::uint8_t v) { bytes_.push_back(v); }
    void u16(std::uint16_t v) { put(v, 2); }
    void u32(std::uint32_t v) { put(v, 4); }
    void u64(std::uint64_t v) { put(v, 8); }
    void f64(double v) {
        std::uint64_t bits = 0;
        std::memcpy(&bits, &v, 8);
        put(bits, 8);
    }
    void vec3(const glm::dvec3& v) {
        f64(v.x);
        f64(v.y);
        f64(v.z);
    }
    void string(const std::string& s) {
        u32(static_cast<std::uint32_t>(s.size()));
        bytes_.insert(bytes_.end(), s.begin(), s.end());
    }
    void raw(std::span<const std::uint8_t> data) {
        bytes_.insert(bytes_.end(), data.begin(), data.end());
    }
    // Overwrites 8 bytes at `at` (for fields known only later, e.g. checksums).
    void patch_u64(std::size_t at, std::uint64_t v) {
        for (int i = 0; i < 8; ++i) bytes_[at + i] = static_cast<std::uint8_t>(v >> (8 * i));
    }
    std::size_t size() const { return bytes_.size(); }
    std::vector<std::uint8_t>& bytes() { return bytes_; }

  private:
    void put(std::uint64_t v, int n) {
        for (int i = 0; i < n; ++i) bytes_.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
    }
    std::vector<std::uint8_t> bytes_;
};

class ByteReader {
  public:
    explicit ByteReader(std::span<const std::uint8_t> data) : data_(data) {}

    std::uint8_t u8() { return static_cast<std::uint8_t>(get(1)); }
    std::uint16_t u16() { return static_cast<std::uint16_t>(get(2)); }
    std::uint32_t u32() { return static_cast<std::uint32_t>(get(4)); }
    std::uint64_t u64() { return get(8); }
    double f64() {
        const std::uint64_t bits = get(8);
        double v = 0.0;
        std::memcpy(&v, &bits, 8);
        return v;
    }
    glm::dvec3 vec3() {
        const double x = f64();
        const double y = f64();
        return {x, y, f64()};
    }
    // Strings longer than `limit` fail the reader (a damaged length must not allocate).
    std::string string(std::size_t limit = 4096) {
        const std::uint32_t n = u32();
        if (n > limit || n > remaining()) {
            failed_ = true;
            return {};
        }
        std::string s(reinterpret_cast<const char*>(data_.data() + pos_), n);
        pos_ += n;
        return s;
    }
    // A view of the next n bytes, or an empty span (and failure) when they are not there.
    std::span<const std::uint8_t> take(std::size_t n) {
        if (n > remaining()) {
            failed_ = true;
            pos_ = data_.size();
            return {};
        }
        auto out = data_.subspan(pos_, n);
        pos_ += n;
        return out;
    }
    void fail() { failed_ = true; }
    bool failed() const { return failed_; }
    std::size_t remaining() const { return data_.size() - pos_; }
    std::size_t position() const { return pos_; }

  private:
    std::uint64_t get(int n) {
        if (static_cast<std::size_t>(n) > remaining()) {
            failed_ = true;
            pos_ = data_.size();
            return 0;
        }
        std::uint64_t v = 0;
        for (int i = 0; i < n; ++i) v |= static_cast<std::uint64_t>(data_[pos_ + i]) << (8 * i);
        pos_ += static_cast<std::size_t>(n);
        return v;
    }
    std::span<const std::uint8_t> data_;
    std::size_t pos_ = 0;
    bool failed_ = false;
};

}  // namespace gem
