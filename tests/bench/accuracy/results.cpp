#include "results.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

namespace gem::accuracy {

Result<ImageError> stone_error(Image test, Image reference, const std::vector<float>& mask) {
    if (mask.size() != test.pixels.size() || mask.size() != reference.pixels.size()) {
        return Error{"stone_error: mask and images differ in size"};
    }
    for (std::size_t i = 0; i < mask.size(); ++i) {
        test.pixels[i].w = mask[i];
        reference.pixels[i].w = mask[i];
    }
    ErrorOptions options;
    options.only_stone = true;
    return compare_images(test, reference, options);
}

namespace {

double finite_psnr(double psnr) {
    return std::isfinite(psnr) ? psnr : 99.0;
}

std::string nd_columns(const Row& r) {
    if (!r.has_nd) return ",,,";
    char text[128];
    std::snprintf(text, sizeof text, "%.3f,%.4f,%.4f,%.5f", finite_psnr(r.error_nd.psnr_db),
                  r.error_nd.delta_e_mean, r.error_nd.delta_e_p99, r.error_nd.share_visible);
    return text;
}

}  // namespace

Result<bool> write_csv(const std::vector<Row>& rows, const std::filesystem::path& path) {
    std::ofstream out(path);
    if (!out) return Error{"cannot write " + path.string()};
    out << "study,scene,view,offset_deg,method,level,spacing_deg,blend,blend_weight,depth,"
           "threshold,"
           "dispersion,samples,compared_with,frame_ms,db_bytes,build_s,psnr_db,de_mean,de_p99,"
           "de_max,share_visible,pixels,nd_psnr_db,nd_de_mean,nd_de_p99,nd_share_visible\n";
    for (const Row& r : rows) {
        char line[640];
        // An identical image has infinite PSNR; gnuplot and spreadsheets read 99 better.
        const double psnr = std::isfinite(r.error.psnr_db) ? r.error.psnr_db : 99.0;
        std::snprintf(line, sizeof line,
                      "%s,%s,%s,%.3f,%s,%d,%g,%d,%.3f,%d,%g,%d,%d,%s,%.3f,%llu,%.3f,%.3f,%.4f,%.4f,"
                      "%.4f,%.5f,%zu,%s\n",
                      r.study.c_str(), r.scene.c_str(), r.view.c_str(), r.offset_deg,
                      r.method.c_str(), r.level, r.spacing_deg, r.blend ? 1 : 0, r.blend_weight,
                      r.depth, r.threshold, r.dispersion ? 1 : 0, r.samples,
                      r.compared_with.c_str(), r.frame_ms,
                      static_cast<unsigned long long>(r.db_bytes), r.build_s, psnr,
                      r.error.delta_e_mean, r.error.delta_e_p99, r.error.delta_e_max,
                      r.error.share_visible, r.error.pixels, nd_columns(r).c_str());
        out << line;
    }
    if (!out) return Error{"error writing " + path.string()};
    return true;
}

void print_header() {
    std::printf(
        "%-9s %-15s %-7s %5s %-9s %4s %4s %-5s %3s %7s %-4s %-9s %9s %8s %6s %6s %6s "
        "%6s %6s %7s\n",
        "study", "scene", "view", "off°", "method", "lvl", "sp°", "mode", "dep", "thr", "disp",
        "vs", "ms/frame", "db MB", "build", "PSNR", "ΔEmean", "ΔEp99", "vis%", "nd:ΔE");
}

void print_row(const Row& r) {
    // mode: a table's view choice, a still picture's frames averaged.
    const std::string mode = r.method == "table"  ? (r.blend ? "blend" : "near")
                             : r.study == "still" ? "x" + std::to_string(r.samples)
                                                  : "-";
    std::printf(
        "%-9s %-15s %-7s %5.1f %-9s %4d %4g %-5s %3d %7g %-4s %-9s %9.1f %8.2f %6.1f "
        "%6.1f %6.2f %6.1f %6.1f %7.2f\n",
        r.study.c_str(), r.scene.c_str(), r.view.c_str(), r.offset_deg, r.method.c_str(), r.level,
        r.spacing_deg, mode.c_str(), r.depth, r.threshold, r.dispersion ? "on" : "off",
        r.compared_with.c_str(), r.frame_ms, double(r.db_bytes) / 1e6, r.build_s,
        std::isfinite(r.error.psnr_db) ? r.error.psnr_db : 99.0, r.error.delta_e_mean,
        r.error.delta_e_p99, 100.0 * r.error.share_visible,
        r.has_nd ? r.error_nd.delta_e_mean : 0.0);
    std::fflush(stdout);
}

}  // namespace gem::accuracy
