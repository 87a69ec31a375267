// Tracer throughput: one 512×512 orthographic ray-table of the default round brilliant in
// diamond, from above and tilted, through the facet planes (convex path) and, with the mesh
// subdivided to about 1,600 triangles, through the triangle BVH (the thesis' largest model had
// 1626 polygons; Lee 2004, Table 8.1). Run: ./bench_tracer --benchmark_counters_tabular=true

#include <benchmark/benchmark.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <tuple>

#include "geometry/cuts.hpp"
#include "trace/parallel.hpp"
#include "trace/tracer.hpp"

namespace gem {
namespace {

constexpr int kSize = 512;
constexpr double kDiamondIndex = 2.417;  // at the sodium D line (GIA Gem Reference Guide)

Stone round_brilliant() {
    Material diamond;
    diamond.name = "diamond";
    diamond.dispersion.kind = Dispersion::Kind::constant;
    diamond.dispersion.coef = {kDiamondIndex};
    Result<Stone> stone = make_cut(default_cut_params(CutShape::round_brilliant), diamond);
    if (!stone) {
        std::fprintf(stderr, "make_cut: %s\n", stone.error().c_str());
        std::abort();
    }
    return std::move(stone).value();
}

// Splits every triangle into 9 coplanar ones (edges in thirds). Points on an edge are computed
// from its lower-numbered end, so both triangles sharing the edge get bit-identical vertices
// and the mesh stays watertight. The result is marked non-convex to force the BVH path.
Stone subdivided_in_nine(const Stone& in) {
    Stone out = in;
    out.name = in.name + " (1/9 triangles, bvh)";
    out.triangles.clear();
    out.convex = false;
    std::map<std::tuple<std::uint32_t, std::uint32_t, int>, std::uint32_t> edge_points;
    auto add = [&](const glm::dvec3& p) {
        out.vertices.push_back(p);
        return static_cast<std::uint32_t>(out.vertices.size() - 1);
    };
    auto on_edge = [&](std::uint32_t u, std::uint32_t v, int k) {  // k thirds from u to v
        if (u > v) std::swap(u, v), k = 3 - k;
        if (k == 0) return u;
        if (k == 3) return v;
        const auto key = std::make_tuple(u, v, k);
        const auto found = edge_points.find(key);
        if (found != edge_points.end()) return found->second;
        const std::uint32_t index =
            add(out.vertices[u] + (k / 3.0) * (out.vertices[v] - out.vertices[u]));
        edge_points[key] = index;
        return index;
    };
    for (const MeshTriangle& tri : in.triangles) {
        const auto [a, b, c] = tri.v;
        const std::uint32_t centre = add((in.vertices[a] + in.vertices[b] + in.vertices[c]) / 3.0);
        // Grid point a + i/3 (b - a) + j/3 (c - a).
        auto grid = [&](int i, int j) {
            if (j == 0) return on_edge(a, b, i);
            if (i == 0) return on_edge(a, c, j);
            if (i + j == 3) return on_edge(b, c, j);
            return centre;  // (1, 1)
        };
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; i + j < 3; ++j) {
                out.triangles.push_back({{grid(i, j), grid(i + 1, j), grid(i, j + 1)}, tri.facet});
                if (i + j < 2) {
                    out.triangles.push_back(
                        {{grid(i + 1, j), grid(i + 1, j + 1), grid(i, j + 1)}, tri.facet});
                }
            }
        }
    }
    return out;
}

struct View {
    glm::dvec3 direction;  // from the camera toward the stone
    glm::dvec3 right, up;
    double half_extent;
};

View orthographic_view(const Stone& stone, double tilt_deg) {
    const double t = tilt_deg * std::numbers::pi / 180.0;
    View v;
    v.direction = {std::sin(t), -std::cos(t), 0.0};
    v.right = {0.0, 0.0, 1.0};
    v.up = glm::cross(v.right, v.direction);
    double radius = 0.0;
    for (const glm::dvec3& p : stone.vertices) radius = std::max(radius, glm::length(p));
    v.half_extent = 1.05 * radius;
    return v;
}

struct TableCounts {
    std::atomic<long> hits{0};
    std::atomic<long> rays_out{0};  // reflected + exit rays stored
    std::atomic<long> segments{0};  // internal segments, at least 1 + highest exit bounce
};

void trace_rows(const Tracer& tracer, const View& view, std::size_t row_begin, std::size_t row_end,
                const TraceSettings& settings, TableCounts& counts) {
    RayList list;
    long hits = 0, rays_out = 0, segments = 0;
    const double pixel = 2.0 * view.half_extent / kSize;
    for (std::size_t y = row_begin; y < row_end; ++y) {
        for (int x = 0; x < kSize; ++x) {
            const double sx = -view.half_extent + (x + 0.5) * pixel;
            const double sy = view.half_extent - (double(y) + 0.5) * pixel;
            const glm::dvec3 origin =
                -4.0 * view.half_extent * view.direction + sx * view.right + sy * view.up;
            tracer.trace({origin, view.direction}, kDiamondIndex, settings, list);
            if (!list.hit) continue;
            ++hits;
            rays_out += 1 + static_cast<long>(list.exits.size());
            int deepest = 0;
            for (const TracedRay& e : list.exits) deepest = std::max<int>(deepest, e.bounces);
            segments += 2 + deepest;  // the pixel ray itself plus the internal chain
        }
    }
    counts.hits += hits;
    counts.rays_out += rays_out;
    counts.segments += segments;
}

void bm_table(benchmark::State& state, const Stone& stone, double tilt_deg, bool all_cores) {
    const Tracer tracer(stone);
    const View view = orthographic_view(stone, tilt_deg);
    const TraceSettings settings;  // 12 segments, weights down to 1e-4
    TableCounts counts;
    for (auto _ : state) {
        if (all_cores) {
            parallel_for(kSize, [&](std::size_t b, std::size_t e) {
                trace_rows(tracer, view, b, e, settings, counts);
            });
        } else {
            trace_rows(tracer, view, 0, kSize, settings, counts);
        }
    }
    const double threads = all_cores ? worker_count() : 1.0;
    const double lists = double(kSize) * kSize * state.iterations();
    state.counters["threads"] = threads;
    state.counters["ray_lists/s"] = benchmark::Counter(lists, benchmark::Counter::kIsRate);
    state.counters["ray_lists/s/core"] =
        benchmark::Counter(lists / threads, benchmark::Counter::kIsRate);
    state.counters["hit_share"] = double(counts.hits) / lists;
    state.counters["rays_out/s"] =
        benchmark::Counter(double(counts.rays_out), benchmark::Counter::kIsRate);
    state.counters["segments/s"] =
        benchmark::Counter(double(counts.segments), benchmark::Counter::kIsRate);
    state.counters["triangles"] = double(stone.triangles.size());
}

void register_all() {
    static const Stone brilliant = round_brilliant();
    static const Stone meshed = subdivided_in_nine(brilliant);
    struct Case {
        const char* name;
        const Stone* stone;
        double tilt;
    };
    const Case cases[] = {{"brilliant_planes/top", &brilliant, 0.0},
                          {"brilliant_planes/tilt30", &brilliant, 30.0},
                          {"brilliant_bvh_split9/top", &meshed, 0.0},
                          {"brilliant_bvh_split9/tilt30", &meshed, 30.0}};
    for (const Case& c : cases) {
        for (bool all : {true, false}) {
            const std::string name = std::string(c.name) + (all ? "/all_cores" : "/one_core");
            benchmark::RegisterBenchmark(
                name.c_str(), [c, all](benchmark::State& s) { bm_table(s, *c.stone, c.tilt, all); })
                ->Unit(benchmark::kMillisecond)
                ->UseRealTime()
                ->MeasureProcessCPUTime();
        }
    }
}

}  // namespace
}  // namespace gem

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    gem::register_all();
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
