#pragma once
// A piece description (config/pieces/README.md): a TOML file naming a setting (solitaire,
// halo, three-stone, band) with its metal, ring size and stones, or a free piece whose stones
// are placed by hand on metal from an OBJ. Stones are stone descriptions (config/stones/),
// scaled to the width the piece asks. Every error names the file, the line and the key
// ("halo.toml:12: small.gap_mm: must be 0.05..2"); a piece whose stones intersect, float off
// their seat or are cut into by the metal is refused with the stones named.

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "piece/piece.hpp"
#include "util/result.hpp"

namespace gem {

// A .glb or .gltf file is read as glTF (gltf_piece.hpp), whose lines (how each stone was
// recognised) go to `log` if given; any other file as a TOML piece description.
Result<Piece> load_piece(const std::filesystem::path& path,
                         std::vector<std::string>* log = nullptr);
// The same from text; `name` stands for the file in messages, `base` resolves relative paths.
Result<Piece> parse_piece(std::string_view text, const std::string& name,
                          const std::filesystem::path& base);

}  // namespace gem
