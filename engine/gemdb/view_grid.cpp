#include "gemdb/view_grid.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <unordered_map>

namespace gem {

namespace {

constexpr double kMinSpacing = 0.002;  // ~0.11°: 3.1 million sphere points
constexpr double kMaxSpacing = 1.0;
constexpr double kMatrixTolerance = 1e-9;
constexpr std::size_t kMaxNearest = 64;
// Views are at least this share of the spacing apart; 0.9 makes the view count close to the
// whole sphere's 4π / spacing² divided by the group order.
constexpr double kMinDistance = 0.9;

// NaN counts as the largest difference, so a matrix of NaNs never passes for a group element.
double max_abs_difference(const glm::dmat3& a, const glm::dmat3& b) {
    double worst = 0.0;
    for (int c = 0; c < 3; ++c) {
        for (int r = 0; r < 3; ++r) {
            const double d = std::abs(a[c][r] - b[c][r]);
            if (!(d <= worst)) worst = std::isnan(d) ? INFINITY : d;
        }
    }
    return worst;
}

int find_element(const std::vector<glm::dmat3>& group, const glm::dmat3& m) {
    for (std::size_t i = 0; i < group.size(); ++i) {
        if (max_abs_difference(group[i], m) < kMatrixTolerance) return static_cast<int>(i);
    }
    return -1;
}

Result<bool> check_group(const std::vector<glm::dmat3>& group) {
    if (group.empty() || max_abs_difference(group[0], glm::dmat3(1.0)) > kMatrixTolerance) {
        return Error{"view grid: symmetry element 0 is not the identity"};
    }
    for (std::size_t i = 0; i < group.size(); ++i) {
        if (max_abs_difference(glm::transpose(group[i]) * group[i], glm::dmat3(1.0)) > 1e-9) {
            return Error{"view grid: symmetry element " + std::to_string(i) +
                         " is not an orthogonal matrix"};
        }
        for (std::size_t j = 0; j < group.size(); ++j) {
            if (find_element(group, group[i] * group[j]) < 0) {
                return Error{"view grid: symmetry is not a group (element " + std::to_string(i) +
                             " times element " + std::to_string(j) + " is not in it)"};
            }
        }
    }
    return true;
}

Result<bool> check_spec(const ViewGridSpec& spec) {
    if (!(spec.spacing_rad >= kMinSpacing && spec.spacing_rad <= kMaxSpacing)) {
        return Error{"view grid: spacing_rad " + std::to_string(spec.spacing_rad) +
                     " is out of range (0.002 .. 1 rad)"};
    }
    if (!(spec.min_elevation_rad >= -std::numbers::pi / 2.0 &&
          spec.min_elevation_rad < std::numbers::pi / 2.0)) {
        return Error{"view grid: min_elevation_rad " + std::to_string(spec.min_elevation_rad) +
                     " is out of range (-pi/2 .. pi/2)"};
    }
    return true;
}

bool full_sphere(const ViewGridSpec& spec) {
    return spec.min_elevation_rad <= -std::numbers::pi / 2.0 + 1e-12;
}

// The fundamental domain is the Voronoi cell of the key among its images; a key moved by no
// element but the identity makes that cell exactly one domain. These candidates are generic
// (no small rational azimuths), so common point groups never fix them.
Result<glm::dvec3> choose_key(const std::vector<glm::dmat3>& group) {
    for (const double azimuth : {0.1234, 0.3571, 0.0617, 0.2713, 0.4429}) {
        for (const double y : {0.37, -0.21, 0.73}) {
            const double r = std::sqrt(1.0 - y * y);
            const glm::dvec3 key{r * std::cos(azimuth), y, r * std::sin(azimuth)};
            bool free = true;
            for (std::size_t i = 1; i < group.size(); ++i) {
                if (glm::length(group[i] * key - key) < 1e-3) free = false;
            }
            if (free) return key;
        }
    }
    return Error{"view grid: no direction is free of the symmetry group (degenerate group)"};
}

// The image of v in the fundamental domain: of all g·v the one nearest the key, the first
// such element on a tie so the result is reproducible.
glm::dvec3 fold(const glm::dvec3& v, const glm::dvec3& key, const std::vector<glm::dmat3>& group) {
    glm::dvec3 best = v;
    double best_dot = glm::dot(v, key);
    for (std::size_t i = 1; i < group.size(); ++i) {
        const glm::dvec3 image = group[i] * v;
        const double d = glm::dot(image, key);
        if (d > best_dot) {
            best_dot = d;
            best = image;
        }
    }
    return best;
}

std::uint64_t hash_cell(const glm::dvec3& p, double cell) {
    const glm::ivec3 c = glm::ivec3(glm::floor((p + 2.0) / cell));
    return (static_cast<std::uint64_t>(c.x) << 42) ^ (static_cast<std::uint64_t>(c.y) << 21) ^
           static_cast<std::uint64_t>(c.z);
}

// Greedy thinning of the folded lattice: a point is kept when every symmetric image of every
// kept point is at least `min_distance` away. Filtering the lattice by the domain instead
// leaves holes near rotation axes, where a domain is thinner than the spacing.
std::vector<std::uint32_t> thin(std::uint32_t n, double min_elevation, double min_distance,
                                const glm::dvec3& key, const std::vector<glm::dmat3>& group) {
    std::unordered_map<std::uint64_t, std::vector<glm::dvec3>> kept_images;
    std::vector<std::uint32_t> kept;
    const double r2 = min_distance * min_distance;
    for (std::uint32_t i = 0; i < n; ++i) {
        const glm::dvec3 p = ViewGrid::sphere_point(i, n);
        if (std::asin(p.y) < min_elevation) continue;
        const glm::dvec3 f = fold(p, key, group);
        bool free = true;
        const glm::ivec3 c = glm::ivec3(glm::floor((f + 2.0) / min_distance));
        for (int dx = -1; dx <= 1 && free; ++dx) {
            for (int dy = -1; dy <= 1 && free; ++dy) {
                for (int dz = -1; dz <= 1 && free; ++dz) {
                    const glm::dvec3 probe =
                        (glm::dvec3(c + glm::ivec3(dx, dy, dz)) + 0.5) * min_distance - 2.0;
                    const auto it = kept_images.find(hash_cell(probe, min_distance));
                    if (it == kept_images.end()) continue;
                    for (const glm::dvec3& q : it->second) {
                        if (glm::dot(q - f, q - f) < r2) free = false;
                    }
                }
            }
        }
        if (!free) continue;
        kept.push_back(i);
        for (const glm::dmat3& g : group) {
            const glm::dvec3 image = g * f;
            kept_images[hash_cell(image, min_distance)].push_back(image);
        }
    }
    return kept;
}

}  // namespace

CameraBasis canonical_basis(const glm::dvec3& view) {
    CameraBasis basis;
    basis.view = glm::normalize(view);
    // Near a pole, -z above and +z below are the limits of projected +y as the view tips
    // over from azimuth 0 (+z), which is also what picture/camera.hpp uses straight above.
    const glm::dvec3 axis = std::abs(basis.view.y) < kPoleCos
                                ? glm::dvec3(0.0, 1.0, 0.0)
                                : glm::dvec3(0.0, 0.0, basis.view.y > 0.0 ? -1.0 : 1.0);
    basis.up = glm::normalize(axis - glm::dot(axis, basis.view) * basis.view);
    basis.right = glm::cross(basis.up, basis.view);
    return basis;
}

glm::dvec3 ViewGrid::sphere_point(std::uint32_t i, std::uint32_t n) {
    // Fibonacci lattice (González, "Measurement of areas on a sphere using Fibonacci and
    // latitude–longitude lattices", Math. Geosci. 42, 2010): equal steps in y, azimuth
    // advancing by the golden angle π(3 − √5). The variant with points on both poles is used
    // because the poles are fixed by every turn about y: without them the few lattice points
    // of a thin domain near a pole, turned round, leave a hole there.
    const double y = 1.0 - 2.0 * i / (n - 1.0);
    const double r = std::sqrt(std::max(0.0, 1.0 - y * y));
    const double phi = i * std::numbers::pi * (3.0 - std::sqrt(5.0));
    return {r * std::cos(phi), y, r * std::sin(phi)};
}

Result<ViewGrid> ViewGrid::build(const ViewGridSpec& spec,
                                 const std::vector<glm::dmat3>& symmetry) {
    if (auto ok = check_spec(spec); !ok) return Error{ok.error()};
    if (auto ok = check_group(symmetry); !ok) return Error{ok.error()};
    ViewGrid grid;
    grid.spec_ = spec;
    for (std::size_t i = 0; i < symmetry.size(); ++i) {
        // Below-range directions are not stored, so only elements keeping elevation fold.
        const glm::dvec3 up = symmetry[i] * glm::dvec3(0.0, 1.0, 0.0);
        if (full_sphere(spec) || glm::length(up - glm::dvec3(0.0, 1.0, 0.0)) < 1e-9) {
            grid.group_.push_back(symmetry[i]);
            grid.group_indices_.push_back(static_cast<std::uint32_t>(i));
        }
    }
    auto key = choose_key(grid.group_);
    if (!key) return Error{key.error()};
    grid.key_ = key.value();
    const double count = std::ceil(4.0 * std::numbers::pi / (spec.spacing_rad * spec.spacing_rad));
    grid.sphere_count_ = static_cast<std::uint32_t>(std::max(count, 8.0));
    std::vector<std::uint32_t> indices =
        thin(grid.sphere_count_, spec.min_elevation_rad, kMinDistance * spec.spacing_rad, grid.key_,
             grid.group_);
    if (auto ok = grid.finish(std::move(indices)); !ok) return Error{ok.error()};
    return grid;
}

Result<ViewGrid> ViewGrid::from_parts(const ViewGridSpec& spec,
                                      const std::vector<glm::dmat3>& symmetry,
                                      std::vector<std::uint32_t> group_indices,
                                      const glm::dvec3& key, std::uint32_t sphere_count,
                                      std::vector<std::uint32_t> sphere_indices) {
    if (auto ok = check_spec(spec); !ok) return Error{ok.error()};
    ViewGrid grid;
    grid.spec_ = spec;
    for (const std::uint32_t index : group_indices) {
        if (index >= symmetry.size()) {
            return Error{"view grid: group element " + std::to_string(index) +
                         " is not in the stone's symmetry list"};
        }
        grid.group_.push_back(symmetry[index]);
    }
    if (auto ok = check_group(grid.group_); !ok) return Error{ok.error()};
    grid.group_indices_ = std::move(group_indices);
    if (!(std::abs(glm::length(key) - 1.0) < 1e-9)) return Error{"view grid: key is not unit"};
    grid.key_ = key;
    const double expected =
        std::ceil(4.0 * std::numbers::pi / (spec.spacing_rad * spec.spacing_rad));
    if (sphere_count != static_cast<std::uint32_t>(std::max(expected, 8.0))) {
        return Error{"view grid: sphere count " + std::to_string(sphere_count) +
                     " does not match the spacing"};
    }
    grid.sphere_count_ = sphere_count;
    for (std::size_t i = 0; i < sphere_indices.size(); ++i) {
        if (sphere_indices[i] >= sphere_count ||
            (i > 0 && sphere_indices[i] <= sphere_indices[i - 1])) {
            return Error{"view grid: view " + std::to_string(i) +
                         " has a sphere index out of order or range"};
        }
    }
    if (auto ok = grid.finish(std::move(sphere_indices)); !ok) return Error{ok.error()};
    return grid;
}

Result<bool> ViewGrid::finish(std::vector<std::uint32_t> sphere_indices) {
    if (sphere_indices.empty()) return Error{"view grid: no view lies in the direction range"};
    sphere_indices_ = std::move(sphere_indices);
    directions_.clear();
    for (const std::uint32_t i : sphere_indices_) {
        directions_.push_back(fold(sphere_point(i, sphere_count_), key_, group_));
    }
    std::vector<std::uint32_t> inverse(group_.size());
    for (std::size_t i = 0; i < group_.size(); ++i) {
        inverse[i] = static_cast<std::uint32_t>(find_element(group_, glm::transpose(group_[i])));
    }
    // Every symmetric image of every stored view, without duplicates of views on mirrors.
    entries_.clear();
    for (std::uint32_t v = 0; v < directions_.size(); ++v) {
        const std::size_t first = entries_.size();
        for (std::size_t h = 0; h < group_.size(); ++h) {
            const glm::dvec3 p = group_[h] * directions_[v];
            const bool seen =
                std::any_of(entries_.begin() + static_cast<std::ptrdiff_t>(first), entries_.end(),
                            [&](const Entry& e) { return glm::length(e.point - p) < 1e-12; });
            if (!seen) entries_.push_back({p, v, inverse[h]});
        }
    }
    cell_size_ = std::max(spec_.spacing_rad, 2.0 / 256.0);
    cells_per_axis_ = static_cast<int>(std::ceil(2.0 / cell_size_)) + 1;
    std::stable_sort(entries_.begin(), entries_.end(), [&](const Entry& a, const Entry& b) {
        return cell_key(cell_of(a.point)) < cell_key(cell_of(b.point));
    });
    cell_keys_.clear();
    cell_starts_.clear();
    for (std::uint32_t i = 0; i < entries_.size(); ++i) {
        const std::uint64_t k = cell_key(cell_of(entries_[i].point));
        if (cell_keys_.empty() || cell_keys_.back() != k) {
            cell_keys_.push_back(k);
            cell_starts_.push_back(i);
        }
    }
    cell_starts_.push_back(static_cast<std::uint32_t>(entries_.size()));
    return true;
}

std::uint64_t ViewGrid::cell_key(const glm::ivec3& cell) const {
    const auto n = static_cast<std::uint64_t>(cells_per_axis_);
    return (static_cast<std::uint64_t>(cell.x) * n + static_cast<std::uint64_t>(cell.y)) * n +
           static_cast<std::uint64_t>(cell.z);
}

glm::ivec3 ViewGrid::cell_of(const glm::dvec3& p) const {
    const glm::dvec3 scaled = glm::floor((p + 1.0) / cell_size_);
    return glm::clamp(glm::ivec3(scaled), glm::ivec3(0), glm::ivec3(cells_per_axis_ - 1));
}

glm::dvec3 ViewGrid::into_range(const glm::dvec3& direction) const {
    if (full_sphere(spec_) ||
        std::asin(std::clamp(direction.y, -1.0, 1.0)) >= spec_.min_elevation_rad) {
        return direction;
    }
    glm::dvec3 horizontal{direction.x, 0.0, direction.z};
    const double length = glm::length(horizontal);
    horizontal = length > 1e-12 ? horizontal / length : glm::dvec3(1.0, 0.0, 0.0);
    return std::cos(spec_.min_elevation_rad) * horizontal +
           glm::dvec3(0.0, std::sin(spec_.min_elevation_rad), 0.0);
}

ViewMatch ViewGrid::nearest(const glm::dvec3& direction) const {
    std::array<ViewMatch, 1> out;
    nearest_k(direction, out);
    return out[0];
}

std::size_t ViewGrid::nearest_k(const glm::dvec3& direction, std::span<ViewMatch> out) const {
    assert(out.size() <= kMaxNearest && !entries_.empty());
    const glm::dvec3 asked = glm::normalize(direction);
    const glm::dvec3 q = into_range(asked);
    const std::size_t k = std::min(out.size(), entries_.size());
    if (k == 0) return 0;
    std::array<double, kMaxNearest> best_d2{};
    std::array<std::uint32_t, kMaxNearest> best{};
    std::size_t found = 0;
    const glm::ivec3 c = cell_of(q);
    // Ring search: after every cell at Chebyshev distance ≤ r is seen, any unseen entry is
    // farther than r cells, i.e. more than r·cell_size away, which bounds the search.
    for (int r = 0; r <= cells_per_axis_; ++r) {
        for (int dx = -r; dx <= r; ++dx) {
            for (int dy = -r; dy <= r; ++dy) {
                const bool side = std::abs(dx) == r || std::abs(dy) == r;
                for (int dz = -r; dz <= r; dz += side ? 1 : std::max(1, 2 * r)) {
                    const glm::ivec3 cell = c + glm::ivec3(dx, dy, dz);
                    if (glm::any(glm::lessThan(cell, glm::ivec3(0))) ||
                        glm::any(glm::greaterThanEqual(cell, glm::ivec3(cells_per_axis_)))) {
                        continue;
                    }
                    const auto it =
                        std::lower_bound(cell_keys_.begin(), cell_keys_.end(), cell_key(cell));
                    if (it == cell_keys_.end() || *it != cell_key(cell)) continue;
                    const auto slot = static_cast<std::size_t>(it - cell_keys_.begin());
                    for (std::uint32_t e = cell_starts_[slot]; e < cell_starts_[slot + 1]; ++e) {
                        const glm::dvec3 d = entries_[e].point - q;
                        const double d2 = glm::dot(d, d);
                        if (found == k && d2 >= best_d2[k - 1]) continue;
                        std::size_t pos = found < k ? found++ : k - 1;
                        while (pos > 0 && best_d2[pos - 1] > d2) {
                            best_d2[pos] = best_d2[pos - 1];
                            best[pos] = best[pos - 1];
                            --pos;
                        }
                        best_d2[pos] = d2;
                        best[pos] = e;
                    }
                }
            }
        }
        const double reach = r * cell_size_;
        if (found == k && best_d2[k - 1] <= reach * reach) break;
    }
    for (std::size_t i = 0; i < found; ++i) {
        const Entry& e = entries_[best[i]];
        const glm::dvec3 folded = group_[e.inverse] * asked;
        const double cosine = std::clamp(glm::dot(folded, directions_[e.view]), -1.0, 1.0);
        out[i] = {e.view, e.inverse, std::acos(cosine)};
    }
    return found;
}

glm::dmat2 ViewGrid::image_map(const ViewMatch& match, const glm::dvec3& asked_view,
                               const glm::dvec3& asked_right, const glm::dvec3& asked_up) const {
    const glm::dmat3& g = group_[match.symmetry];
    const glm::dvec3 s = directions_[match.view];
    const glm::dvec3 a = glm::normalize(g * asked_view);
    // Rodrigues rotation by the small angle from a to s about their common normal.
    glm::dmat3 turn(1.0);
    const glm::dvec3 axis = glm::cross(a, s);
    const double sine = glm::length(axis);
    if (sine > 1e-15) {
        const glm::dvec3 k = axis / sine;
        const double cosine = glm::dot(a, s);
        const glm::dmat3 cross{{0.0, k.z, -k.y}, {-k.z, 0.0, k.x}, {k.y, -k.x, 0.0}};
        turn = cosine * glm::dmat3(1.0) + (1.0 - cosine) * glm::outerProduct(k, k) + sine * cross;
    }
    const glm::dvec3 r = turn * (g * asked_right);
    const glm::dvec3 u = turn * (g * asked_up);
    const CameraBasis b = canonical_basis(s);
    return glm::dmat2{{glm::dot(r, b.right), glm::dot(r, b.up)},
                      {glm::dot(u, b.right), glm::dot(u, b.up)}};
}

}  // namespace gem
