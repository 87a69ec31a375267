#pragma once
// A piece of jewellery: its metal and any number of stones, each with its own cut or design,
// material and placement, in the piece's frame (millimetres; y up through the centre stone's
// table, the finger along x for a ring). Identical stones are one entry of `kinds` that several
// placements share, so they are traced, uploaded and built once. The CPU reference, gemrender
// and the GPU's frame renderer take a piece as this one description (the kiosk's catalogue
// rings are pieces of one stone, made by the solitaire setting).

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "geometry/stone.hpp"
#include "piece/metal_mesh.hpp"
#include "piece/placement.hpp"

namespace gem {

struct PieceStone {
    std::size_t kind = 0;  // index into Piece::kinds
    Placement placement;
    std::string role;  // "centre", "halo 7", "side 2": for messages and logs
};

// A claw tip or a bead: a ball of metal that bears on one stone's crown and holds it.
struct Hold {
    std::size_t stone = 0;   // index into Piece::stones
    glm::dvec3 centre{0.0};  // piece frame
    double radius = 0.0;
};

// Where a kind of stone came from: its stone description and the girdle width the piece sized
// it to (0: the description's own). What makes the same stone again elsewhere, e.g. its tables
// (gemtables build --width-mm).
struct KindSource {
    std::filesystem::path description;
    double width_mm = 0.0;
};

struct Piece {
    std::string name;
    std::vector<Stone> kinds;
    std::vector<KindSource> kind_sources;  // by kind, for a piece read from a file; else empty
    std::vector<PieceStone> stones;        // the first is the centre stone, the hero of the picture
    MetalMesh metal;
    std::vector<Hold> holds;
    // The point of the file a piece was read from (glTF, millimetres, its axes) that is now the
    // piece's origin: where its centre stone was, when the file's origin lay outside it (CAD's
    // finger centre). Zero for pieces made here and files whose origin is the stone's.
    glm::dvec3 file_origin_mm{0.0};

    const Stone& stone_of(std::size_t i) const { return kinds[stones[i].kind]; }
    // Radius of the sphere about the piece's origin that holds every stone and the metal.
    double radius_mm() const;
};

// The one line gemrender prints for a piece:
// "piece NAME: N stones (K distinct), M metal triangles".
std::string describe(const Piece& piece);

}  // namespace gem
