#include "piece/gltf_piece_frame.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "geometry/stone.hpp"
#include "geometry/triangulate.hpp"

namespace gem {

// How many millimetres one of the file's units is. glTF says metres, and most exporters
// convert; some write CAD's millimetres as they are, which makes a 20 mm ring 20 m across. A
// piece of jewellery is between a 0.3 mm melee and a 400 mm necklace: metres when that makes
// it so, else millimetres when that does.
double millimetres_per_unit(const import::GltfDocument& doc, std::string& why) {
    glm::dvec3 lo(HUGE_VAL), hi(-HUGE_VAL);
    for (const import::GltfPart& part : doc.parts) {
        for (const glm::dvec3& p : part.positions) {
            const glm::dvec3 q(part.to_scene * glm::dvec4(p, 1.0));
            lo = glm::min(lo, q);
            hi = glm::max(hi, q);
        }
    }
    const double across = glm::length(hi - lo);
    const auto jewellery = [](double mm) { return mm >= 0.3 && mm <= 400.0; };
    if (!(across > 0.0) || jewellery(across * 1000.0) || !jewellery(across)) return 1000.0;
    char text[200];
    std::snprintf(text, sizeof text,
                  "read in millimetres, not glTF's metres: the piece is %.4g units across, and "
                  "no piece of jewellery is %.4g m",
                  across, across);
    why = text;
    return 1.0;
}

// The piece turned so that its centre stone's table faces +y, the piece's up, where the file
// put it facing another axis (CAD's z up, written without turning). Only a stone whose largest
// facet is half as large again as any other (a table) says which way is up, and only when it
// lies within 30° of an axis other than +y. Returns what was done, or empty.
std::string turn_table_up(Piece& piece) {
    if (piece.stones.empty()) return {};
    const Stone& hero = piece.stone_of(0);
    double largest = 0.0, second = 0.0;
    glm::dvec3 table(0.0);
    for (const Facet& f : hero.facets) {
        const double a = loop_area(hero.vertices, f.loop);
        if (a > largest) {
            second = largest;
            largest = a;
            table = f.plane.n;
        } else {
            second = std::max(second, a);
        }
    }
    if (!(largest > 1.5 * second)) return {};
    const glm::dvec3 up = glm::normalize(piece.stones[0].placement.rotation * table);
    const double cos30 = std::cos(std::numbers::pi / 6.0);
    if (up.y > cos30) return {};
    glm::dmat3 turn(1.0);
    std::string axis;
    // Columns of glm matrices: turn * up = +y.
    if (up.z > cos30) {
        turn = glm::dmat3(glm::dvec3(1, 0, 0), glm::dvec3(0, 0, -1), glm::dvec3(0, 1, 0));
        axis = "+z";
    } else if (up.z < -cos30) {
        turn = glm::dmat3(glm::dvec3(1, 0, 0), glm::dvec3(0, 0, 1), glm::dvec3(0, -1, 0));
        axis = "-z";
    } else if (up.x > cos30) {
        turn = glm::dmat3(glm::dvec3(0, 1, 0), glm::dvec3(-1, 0, 0), glm::dvec3(0, 0, 1));
        axis = "+x";
    } else if (up.x < -cos30) {
        turn = glm::dmat3(glm::dvec3(0, -1, 0), glm::dvec3(1, 0, 0), glm::dvec3(0, 0, 1));
        axis = "-x";
    } else if (up.y < -cos30) {
        turn = glm::dmat3(glm::dvec3(1, 0, 0), glm::dvec3(0, -1, 0), glm::dvec3(0, 0, -1));
        axis = "-y";
    } else {
        return {};
    }
    for (PieceStone& s : piece.stones) {
        s.placement.rotation = turn * s.placement.rotation;
        s.placement.position = turn * s.placement.position;
    }
    const glm::mat3 t(turn);
    for (glm::vec3& p : piece.metal.positions) p = t * p;
    for (glm::vec3& n : piece.metal.normals) n = t * n;
    return "turned so that up is +y: the centre stone's table faced " + axis +
           " (the file was written with another axis up)";
}

// The centre stone at the piece's origin, as the settings place it (settings.hpp): CAD puts
// the origin at the finger's centre, and the view orbits the origin, so a ring from CAD turned
// about the finger with its stone 13 mm off the picture's centre (the GPU's virtual cube was
// then also taken from the origin, where the stone came out black; each stone now has its own,
// piece/sight_groups.hpp). A file whose origin lies within the centre stone (this project's
// own, a loose stone's) keeps it.
void centre_on_the_centre_stone(Piece& piece) {
    if (piece.stones.empty()) return;
    const glm::dvec3 centre = piece.stones.front().placement.position;
    if (!(glm::length(centre) > bounding_radius(piece.stone_of(0).vertices))) return;
    for (PieceStone& s : piece.stones) s.placement.position -= centre;
    for (glm::vec3& p : piece.metal.positions) p -= glm::vec3(centre);
    piece.file_origin_mm = centre;
}

std::string beyond_reach(const Piece& piece) {
    double farthest = 0.0;
    bool finite = true;
    const auto reach = [&](const glm::dvec3& p) {
        const double d = glm::length(p);
        finite = finite && std::isfinite(d);
        farthest = std::max(farthest, d);
    };
    for (const glm::vec3& p : piece.metal.positions) reach(glm::dvec3(p));
    for (std::size_t i = 0; i < piece.stones.size(); ++i) {
        for (const glm::dvec3& v : piece.stone_of(i).vertices) {
            reach(piece.stones[i].placement.to_piece(v));
        }
    }
    if (!finite) {
        return "a corner of the piece is not a finite number of millimetres";
    }
    if (!(farthest > kFarthestCornerMm)) return {};
    char text[200];
    std::snprintf(text, sizeof text,
                  "a corner of the piece lies %.3g mm from its centre stone (at most %.0f mm: not "
                  "a piece of jewellery, or in units the file does not say)",
                  farthest, kFarthestCornerMm);
    return text;
}

}  // namespace gem
