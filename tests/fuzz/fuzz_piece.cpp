// libFuzzer target: any bytes handed to the piece reader (parse_piece), resolved against the
// shipped config/pieces folder so that inputs may name the real stone descriptions and reach
// the settings and the piece check, and to the reader of the TOML manifest beside a glTF piece
// (parse_gltf_manifest). Each must answer each input with a result or an Error naming the
// file, never a crash, a sanitizer report, an assertion or a runaway allocation.
// Seeds: the shipped pieces (config/pieces/*.toml).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "piece/gltf_manifest.hpp"
#include "piece/piece_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size > 16 * 1024) return 0;  // a piece file is a few hundred bytes
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    (void)gem::parse_piece(text, "fuzz.toml", GEM_PIECES_DIR);
    (void)gem::parse_gltf_manifest(text, "fuzz.glb.toml");
    return 0;
}
