// libFuzzer target: any bytes handed to the glTF piece reader (parse_gltf_piece: the glTF
// library, the accessors, the node tree, the stones' facets and the piece check). The reader
// must answer each input with a piece or an Error naming the file, never a crash, a sanitizer
// report, an assertion or a runaway allocation. Seeds: gem_fuzz_seeds' glTF pieces.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "piece/gltf_piece.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size > 256 * 1024) return 0;  // the seeds are a few kilobytes
    const std::string_view bytes(reinterpret_cast<const char*>(data), size);
    // No folder to look in: a .gltf naming outside buffers gets an error, not a file.
    (void)gem::parse_gltf_piece(bytes, "fuzz.glb", "/nonexistent");
    return 0;
}
