#include "util/cube_faces.hpp"

#include <algorithm>
#include <cmath>

namespace gem {

glm::dvec3 cube_face_direction(int face, double s, double t) {
    // (sc, tc, ma) per major axis, s = (sc/|ma| + 1)/2, solved for the direction.
    const double sc = 2.0 * s - 1.0;
    const double tc = 2.0 * t - 1.0;
    glm::dvec3 d(0.0);
    switch (face) {
        case 0:
            d = {1.0, -tc, -sc};
            break;
        case 1:
            d = {-1.0, -tc, sc};
            break;
        case 2:
            d = {sc, 1.0, tc};
            break;
        case 3:
            d = {sc, -1.0, -tc};
            break;
        case 4:
            d = {sc, -tc, 1.0};
            break;
        default:
            d = {-sc, -tc, -1.0};
            break;
    }
    return glm::normalize(d);
}

CubeTexel cube_face_texel(const glm::dvec3& r, int side) {
    const glm::dvec3 a = glm::abs(r);
    CubeTexel out;
    double sc, tc, ma;
    if (a.x >= a.y && a.x >= a.z) {
        out.face = r.x >= 0.0 ? 0 : 1;
        sc = r.x >= 0.0 ? -r.z : r.z;
        tc = -r.y;
        ma = a.x;
    } else if (a.y >= a.z) {
        out.face = r.y >= 0.0 ? 2 : 3;
        sc = r.x;
        tc = r.y >= 0.0 ? r.z : -r.z;
        ma = a.y;
    } else {
        out.face = r.z >= 0.0 ? 4 : 5;
        sc = r.z >= 0.0 ? r.x : -r.x;
        tc = -r.y;
        ma = a.z;
    }
    auto texel = [side](double c) {
        return std::clamp(static_cast<int>(std::floor(0.5 * (c + 1.0) * side)), 0, side - 1);
    };
    out.s = texel(sc / ma);
    out.t = texel(tc / ma);
    return out;
}

}  // namespace gem
