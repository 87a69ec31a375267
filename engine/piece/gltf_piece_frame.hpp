#pragma once
// Where a piece read from glTF stands: CAD exports are not always what glTF says (metres, +y
// up), and CAD's origin is the finger's centre, not the centre stone. Each of these looks at
// the file or the piece, puts it right, and says so for the reader's warning line
// (gltf_piece.hpp, docs/gltf.md).

#include <string>

#include "import/gltf_document.hpp"
#include "piece/piece.hpp"

namespace gem {

// How many millimetres one of the file's units is: 1000 (glTF's metres), or 1 when the file is
// only the size of a piece of jewellery in millimetres; `why` then says so.
double millimetres_per_unit(const import::GltfDocument& doc, std::string& why);

// The piece turned so that its centre stone's table faces +y; what was done, or empty.
std::string turn_table_up(Piece& piece);

// The centre stone put at the piece's origin when the file's origin lies outside it
// (Piece::file_origin_mm keeps where it was).
void centre_on_the_centre_stone(Piece& piece);

// Why the piece, centred, cannot be shown: a corner of its metal or of a placed stone that is not
// a number or lies further than kFarthestCornerMm (piece/metal_mesh.hpp) from its origin; empty
// when none does.
std::string beyond_reach(const Piece& piece);

}  // namespace gem
