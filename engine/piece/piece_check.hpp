#pragma once
// A piece checked as a jeweller would before it is shown: no two stones intersect, and every
// stone is held, with metal touching it (within kHeldMm) and nowhere cutting into it deeper
// than a setter's seat. A piece from a file that fails gets one message naming the stones by
// their roles; settings made here pass by construction and are tested to. The metal is judged
// by its vertices and the stone's corners: metal that passes through a stone between them (an
// edge across a facet) is not seen here; the settings' tests cast rays for that.

#include <string>
#include <vector>

#include "piece/piece.hpp"
#include "util/result.hpp"

namespace gem {

// The farthest the metal may stand from a stone that it holds.
inline constexpr double kHeldMm = 0.1;

// `rounding_mm`: how far the file the piece was read from may have moved its corners (a
// quantised glTF's step), allowed on top of the seat and the hold. The first problem found.
Result<bool> check_piece(const Piece& piece, double rounding_mm = 0.0);

// One problem, and which of the checks found it.
struct PieceProblem {
    enum class Kind { stones_intersect, metal_cuts_in, stone_floats };
    Kind kind;
    std::string message;  // names the stones by their roles
};

// Every problem: what a piece from CAD is shown with, as warnings (an uncut seat, a loose stone
// with no metal), where a piece description is refused.
std::vector<PieceProblem> piece_problems(const Piece& piece, double rounding_mm = 0.0);

// Whether the two placed stones share any volume (their surfaces cross, or one holds the
// other); stones that only touch do not.
bool stones_intersect(const Stone& a, const Placement& pa, const Stone& b, const Placement& pb);

}  // namespace gem
