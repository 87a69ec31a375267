#include "piece/metal_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace gem {

namespace {
constexpr double kPi = 3.14159265358979323846;
}  // namespace

glm::dmat3 frame_from_up(const glm::dvec3& up, const glm::dvec3& along) {
    const glm::dvec3 y = glm::normalize(up);
    const glm::dvec3 x = glm::normalize(along - glm::dot(along, y) * y);
    const glm::dvec3 z = glm::cross(x, y);  // right-handed: x × y = z
    return glm::dmat3(x, y, z);
}

double MetalMesh::radius_mm() const {
    double r2 = 0.0;
    for (const glm::vec3& p : positions) r2 = std::max(r2, double(glm::dot(p, p)));
    return std::sqrt(r2);
}

int circle_segments(double radius_mm, int multiple_of) {
    const int m = std::max(multiple_of, 1);
    const double cosine = 1.0 - kChordToleranceMm / std::max(radius_mm, kChordToleranceMm);
    const int fewest = static_cast<int>(std::ceil(kPi / std::acos(cosine)));
    return std::max(m * ((fewest + m - 1) / m), 3);
}

std::uint32_t MeshBuilder::vertex(const glm::dvec3& p, const glm::dvec3& n) {
    mesh_.positions.emplace_back(frame_.to_piece(p));
    mesh_.normals.emplace_back(glm::normalize(frame_.direction_to_piece(n)));
    return static_cast<std::uint32_t>(mesh_.positions.size() - 1);
}

// Wound so that the face's geometric normal agrees with its vertices' analytic normals: the
// solids below then need not track orientation through their parametrisations.
void MeshBuilder::triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    const glm::vec3 g = glm::cross(mesh_.positions[b] - mesh_.positions[a],
                                   mesh_.positions[c] - mesh_.positions[a]);
    const glm::vec3 n = mesh_.normals[a] + mesh_.normals[b] + mesh_.normals[c];
    if (glm::dot(g, n) < 0.0f) std::swap(b, c);
    mesh_.indices.insert(mesh_.indices.end(), {a, b, c});
}

void MeshBuilder::quad(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
    triangle(a, b, c);
    triangle(a, c, d);
}

void MeshBuilder::torus(const glm::dvec3& c, const glm::dvec3& e0, const glm::dvec3& e1, double r,
                        double radial, double axial, int segments, int profile) {
    const glm::dvec3 axis = glm::cross(e0, e1);
    std::vector<std::uint32_t> ids;
    for (int i = 0; i < segments; ++i) {
        const double phi = 2.0 * kPi * i / segments;
        const glm::dvec3 out = std::cos(phi) * e0 + std::sin(phi) * e1;
        for (int j = 0; j < profile; ++j) {
            const double theta = 2.0 * kPi * j / profile;
            const glm::dvec3 p =
                c + (r + radial * std::cos(theta)) * out + axial * std::sin(theta) * axis;
            // The ellipse's normal: the gradient of (u/a)² + (v/b)².
            const glm::dvec3 n = std::cos(theta) / radial * out + std::sin(theta) / axial * axis;
            ids.push_back(vertex(p, n));
        }
    }
    auto at = [&](int i, int j) {
        return ids[static_cast<std::size_t>((i % segments) * profile + (j % profile))];
    };
    for (int i = 0; i < segments; ++i) {
        for (int j = 0; j < profile; ++j)
            quad(at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
    }
}

void MeshBuilder::cylinder(const glm::dvec3& a, const glm::dvec3& c, double radius,
                           const glm::dvec3& e1, int sides) {
    // A wire of no length has no wall (the spheres at its ends round the joint); normalising
    // it would put NaNs into the mesh. An `e1` along the axis gives way to any perpendicular.
    const double length = glm::length(c - a);
    if (!(length > 1e-9)) return;
    const glm::dvec3 axis = (c - a) / length;
    glm::dvec3 across = e1 - glm::dot(e1, axis) * axis;
    if (!(glm::length(across) > 1e-9)) {
        const glm::dvec3 other = std::abs(axis.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 0, 1);
        across = other - glm::dot(other, axis) * axis;
    }
    const glm::dvec3 u = glm::normalize(across);
    const glm::dvec3 v = glm::cross(axis, u);
    std::vector<std::uint32_t> side_a, side_c, cap_a, cap_c;
    for (int j = 0; j < sides; ++j) {
        const double theta = 2.0 * kPi * j / sides;
        const glm::dvec3 radial = std::cos(theta) * u + std::sin(theta) * v;
        side_a.push_back(vertex(a + radius * radial, radial));
        side_c.push_back(vertex(c + radius * radial, radial));
        cap_a.push_back(vertex(a + radius * radial, -axis));
        cap_c.push_back(vertex(c + radius * radial, axis));
    }
    const std::uint32_t centre_a = vertex(a, -axis);
    const std::uint32_t centre_c = vertex(c, axis);
    for (int j = 0; j < sides; ++j) {
        const int k = (j + 1) % sides;
        quad(side_a[j], side_a[k], side_c[k], side_c[j]);
        triangle(centre_a, cap_a[k], cap_a[j]);
        triangle(centre_c, cap_c[j], cap_c[k]);
    }
}

void MeshBuilder::sphere(const glm::dvec3& c, double radius, int rings, int sides) {
    const std::uint32_t south = vertex(c - glm::dvec3(0, radius, 0), {0, -1, 0});
    const std::uint32_t north = vertex(c + glm::dvec3(0, radius, 0), {0, 1, 0});
    std::vector<std::uint32_t> ids;
    for (int i = 1; i < rings; ++i) {
        const double lat = -0.5 * kPi + kPi * i / rings;
        for (int j = 0; j < sides; ++j) {
            const double lon = 2.0 * kPi * j / sides;
            const glm::dvec3 n(std::cos(lat) * std::cos(lon), std::sin(lat),
                               std::cos(lat) * std::sin(lon));
            ids.push_back(vertex(c + radius * n, n));
        }
    }
    auto at = [&](int i, int j) { return ids[static_cast<std::size_t>(i * sides + j % sides)]; };
    for (int j = 0; j < sides; ++j) {
        triangle(south, at(0, j), at(0, j + 1));
        triangle(north, at(rings - 2, j + 1), at(rings - 2, j));
        for (int i = 0; i + 1 < rings - 1; ++i)
            quad(at(i, j), at(i, j + 1), at(i + 1, j + 1), at(i + 1, j));
    }
}

}  // namespace gem
