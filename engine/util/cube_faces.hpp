#pragma once
// Cube-map addressing as OpenGL ES lays it out (OpenGL ES 3.0.6 §3.8.10, table 3.21): faces
// 0..5 = +x, -x, +y, -y, +z, -z, and on each face (s, t) in [0, 1]² with t = 0 the face's first
// row in memory. The GPU's cube textures (the environment, the trace method's first-guess map)
// and the CPU code that fills or reads them share it.

#include <glm/glm.hpp>

namespace gem {

// The unit direction through (s, t) of cube face `face`.
glm::dvec3 cube_face_direction(int face, double s, double t);

// The face and texel (of `side` × `side`) a direction falls in: the inverse of the above.
struct CubeTexel {
    int face = 0;
    int s = 0;
    int t = 0;
};
CubeTexel cube_face_texel(const glm::dvec3& direction, int side);

}  // namespace gem
