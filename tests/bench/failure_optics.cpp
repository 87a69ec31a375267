// Pictures and the depth sweep for docs/failure-modes-optics.md: truncated energy per pixel of
// a round brilliant for moissanite, diamond and quartz at depths 4, 8 and 16, the depth each
// needs to keep the loss under 1 %, and the ΔE00 map of a moissanite view shaded before and
// after the table codec. Usage: failure_optics [output folder] (default
// docs/images/failures), run from the repository root.

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "gemdb/database_types.hpp"
#include "gemdb/payload.hpp"
#include "gemdb/view_grid.hpp"
#include "geometry/cuts.hpp"
#include "picture/image_error.hpp"
#include "scene/environment.hpp"
#include "scene/shading.hpp"
#include "trace/tracer.hpp"

namespace {

using namespace gem;

constexpr std::uint32_t kSide = 128;
constexpr double kField = 7.0;

Stone brilliant(const std::string& material) {
    Material m = find_material(material).value();
    m.dispersion = Dispersion::constant_index(m.index(kFraunhoferD));
    return make_cut(default_cut_params(CutShape::round_brilliant), m).value();
}

std::vector<RayList> trace_view(const Stone& stone, const TraceSettings& settings) {
    const Tracer tracer(stone);
    const CameraModel camera{CameraModel::Kind::orthographic, 0.0, kField};
    const CameraBasis basis = canonical_basis(glm::normalize(glm::dvec3(0.25, 1.0, 0.15)));
    std::vector<RayList> lists(std::size_t(kSide) * kSide);
    for (std::uint32_t row = 0; row < kSide; ++row) {
        for (std::uint32_t col = 0; col < kSide; ++col) {
            tracer.trace(camera_ray(camera, basis, pixel_centre(col, row, kSide, kField)),
                         stone.material.index(), settings, lists[std::size_t(row) * kSide + col]);
        }
    }
    return lists;
}

void paste(Image& panel, const Image& tile, int x0, int y0) {
    for (int y = 0; y < tile.height; ++y) {
        for (int x = 0; x < tile.width; ++x) panel.at(x0 + x, y0 + y) = tile.at(x, y);
    }
}

void save(const Image& image, const std::filesystem::path& path) {
    auto written = write_png(image, path);
    std::printf("%s\n", written ? path.c_str() : written.error().c_str());
}

// Rows: materials; columns: depths. Heat map of the truncated weight, white at 0.5.
void truncation_panel(const std::filesystem::path& out) {
    const std::vector<std::string> materials = {"moissanite", "diamond", "quartz"};
    const std::vector<int> depths = {4, 8, 16};
    Image panel(int(kSide * depths.size()), int(kSide * materials.size()));
    std::printf("%-11s %8s %8s   depth for mean < 1 %% / p99 < 1 %% / max < 1 %%\n", "material",
                "n", "mean@12");
    for (std::size_t m = 0; m < materials.size(); ++m) {
        const Stone stone = brilliant(materials[m]);
        for (std::size_t d = 0; d < depths.size(); ++d) {
            TraceSettings settings;
            settings.max_depth = depths[d];
            settings.min_weight = 0.0;
            const auto lists = trace_view(stone, settings);
            std::vector<float> truncated(lists.size(), 0.0f);
            for (std::size_t p = 0; p < lists.size(); ++p) {
                truncated[p] = float(lists[p].truncated_weight);
            }
            paste(panel, heat_map(truncated, int(kSide), int(kSide), 0.5f), int(kSide * d),
                  int(kSide * m));
        }
        // Depth sweep: the first depth at which the mean, the 99th percentile and the worst
        // pixel of the truncated weight fall under 1 %.
        int found[3] = {-1, -1, -1};
        double at12 = 0.0;
        for (int depth = 1; depth <= 400 && found[2] < 0; ++depth) {
            TraceSettings settings;
            settings.max_depth = depth;
            settings.min_weight = 0.0;
            std::vector<double> t;
            for (const RayList& l : trace_view(stone, settings)) {
                if (l.hit) t.push_back(l.truncated_weight);
            }
            std::sort(t.begin(), t.end());
            double mean = 0.0;
            for (double v : t) mean += v / double(t.size());
            if (depth == 12) at12 = mean;
            const double stats[3] = {mean, t[t.size() * 99 / 100], t.back()};
            for (int s = 0; s < 3; ++s) {
                if (found[s] < 0 && stats[s] < 0.01) found[s] = depth;
            }
        }
        std::printf("%-11s %8.4f %8.4f   %d / %d / %d\n", materials[m].c_str(),
                    stone.material.index(), at12, found[0], found[1], found[2]);
    }
    save(panel, out / "optics-truncated-energy.png");
}

// Exact shading | after the payload codec ΔE00 heat map (white at ΔE00 = 1).
void codec_panel(const std::filesystem::path& out) {
    Stone stone = brilliant("moissanite");
    const auto lists = trace_view(stone, TraceSettings{});
    PositionBox box{stone.vertices[0], stone.vertices[0]};
    for (const glm::dvec3& v : stone.vertices) {
        box.min = glm::min(box.min, v);
        box.max = glm::max(box.max, v);
    }
    std::vector<std::uint8_t> raw;
    DecodedView view;
    if (!encode_payload(lists, nullptr, kSide, box, 1e-4, raw) ||
        !decode_payload(raw, kSide, false, box, view)) {
        std::printf("codec failed\n");
        return;
    }
    const Environment studio = Environment::studio();
    ShadingSettings shading;
    shading.lights.push_back({{30.0, 100.0, 40.0}, false, glm::dvec3(3.0)});
    const Shader shader(stone, stone.material, studio, shading);
    Image exact(kSide, kSide), decoded(kSide, kSide);
    for (std::size_t p = 0; p < lists.size(); ++p) {
        if (!lists[p].hit) continue;
        const RayList d = ray_list_at(view, p);
        const int x = int(p % kSide), y = int(p / kSide);
        exact.at(x, y) = glm::vec4(glm::vec3(shader.shade(lists[p])), 1.0f);
        decoded.at(x, y) = glm::vec4(glm::vec3(shader.shade(d)), 1.0f);
    }
    ErrorOptions options;
    options.only_stone = true;
    if (auto e = compare_images(decoded, exact, options)) {
        std::printf(
            "codec (128 px moissanite, studio + light): PSNR %.1f dB, dE00 mean %.4f "
            "p99 %.4f max %.4f\n",
            e.value().psnr_db, e.value().delta_e_mean, e.value().delta_e_p99,
            e.value().delta_e_max);
    }
    Image panel(2 * int(kSide), int(kSide));
    paste(panel, exact, 0, 0);
    paste(panel, heat_map(delta_e_map(decoded, exact), int(kSide), int(kSide), 1.0f), int(kSide),
          0);
    save(panel, out / "optics-codec-delta-e.png");
}

}  // namespace

int main(int argc, char** argv) {
    const std::filesystem::path out = argc > 1 ? argv[1] : "docs/images/failures";
    std::filesystem::create_directories(out);
    truncation_panel(out);
    codec_panel(out);
    return 0;
}
