// Gemmological sweep of the round brilliant in diamond with the exact tracer (engine/gemmology):
// face-up light return, leakage, ASET zones and fire as functions of the pavilion angle (crown
// 34.5°, table 53 %) and of the crown angle (pavilion 40.75°), plus light-return and ASET
// pictures of the Tolkowsky stone, a deep ("nailhead") and a shallow ("fisheye") one.
//
// Run from the repository root (or pass it):  build/<dir>/tests/bench/bench_gemmology [ROOT]
// Writes ROOT/docs/gemmology/*.csv, ROOT/docs/images/gemmology/*.png and, when gnuplot is on
// the PATH, the charts ROOT/docs/images/gemmology/*.png from the scripts written beside them.
// Google Benchmark is linked by the bench folder but not used: this prints figures, not times.

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "gemmology/face_up.hpp"
#include "gemmology/face_up_images.hpp"
#include "geometry/cuts.hpp"
#include "optics/material.hpp"

namespace gem {
namespace {

namespace fs = std::filesystem;

constexpr int kSweepResolution = 128;  // pixels across the girdle for the sweeps
constexpr int kImageResolution = 256;  // for the pictures

Stone brilliant(double pavilion_deg, double crown_deg) {
    CutParams p = default_cut_params(CutShape::round_brilliant);
    p.pavilion_angle_deg = pavilion_deg;
    p.crown_angle_deg = crown_deg;
    Result<Stone> stone = make_cut(p, *find_material("diamond"));
    if (!stone) {
        std::fprintf(stderr, "bench_gemmology: %s\n", stone.error().c_str());
        std::exit(1);
    }
    return std::move(stone).value();
}

struct Row {
    double pavilion = 0.0;
    double crown = 0.0;
    FaceUpTotals t;              // averaged over kViews
    double centre = 0.0;         // face-up light return within 0.15 girdle radii of the axis
    double table_leakage = 0.0;  // face-up: leakage of the rays that enter through the table
};

double table_leakage(const FaceUpAnalysis& a) {
    double sum = 0.0;
    int n = 0;
    for (const FaceUpPixel& px : a.pixels) {
        if (!px.table) continue;
        sum += px.zone[static_cast<std::size_t>(SkyZone::below)];
        ++n;
    }
    return n > 0 ? sum / n : 0.0;
}

// Face-up and the stone rocked by 5° and 10° toward a pavilion main (azimuth 0°) and half
// way between two mains (22.5°); by the stone's 8-fold symmetry and mirror planes these stand
// for every direction of tilt.
const std::vector<ViewTilt> kViews{{0.0, 0.0}, {5.0, 0.0}, {5.0, 22.5}, {10.0, 0.0}, {10.0, 22.5}};

Row measure(double pavilion, double crown, int resolution) {
    FaceUpSettings s;
    s.resolution = resolution;
    const Stone stone = brilliant(pavilion, crown);
    const FaceUpAnalysis face_up = analyse_face_up(stone, s);
    return {pavilion, crown, tilt_averaged_totals(stone, s, kViews),
            mean_light_return(face_up, 0.0, 0.15), table_leakage(face_up)};
}

constexpr const char* kHeader =
    "pavilion_deg,crown_deg,light_return,surface_return,centre_return,red_45_75,green_0_45,"
    "blue_head,black_leakage,truncated,fire_deg,mean_spread_deg,table_leakage,hemisphere_return";

void print_row(const Row& r, std::FILE* out, bool csv) {
    const FaceUpTotals& t = r.t;
    const auto z = [&](SkyZone k) { return t.zone[static_cast<std::size_t>(k)]; };
    std::fprintf(out,
                 csv ? "%.2f,%.2f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f\n"
                     : "%7.2f %6.2f %7.4f %7.4f %7.4f %7.4f %7.4f %7.4f %7.4f %7.4f %7.4f %7.4f "
                       "%7.4f %7.4f\n",
                 r.pavilion, r.crown, t.light_return, t.surface_return, r.centre,
                 z(SkyZone::high_sky), z(SkyZone::low_sky), z(SkyZone::head), z(SkyZone::below),
                 t.truncated, t.fire_deg, t.mean_spread_deg, r.table_leakage, t.hemisphere_return);
}

std::vector<Row> sweep(const char* title, const std::vector<double>& pavilions,
                       const std::vector<double>& crowns, const fs::path& csv_path) {
    std::printf("\n%s (%d px across the girdle; means over %zu views, centre face-up)\n", title,
                kSweepResolution, kViews.size());
    std::printf("%7s %6s %7s %7s %7s %7s %7s %7s %7s %7s %7s %7s %7s %7s\n", "pav", "crown", "LR",
                "surf", "centre", "red", "green", "blue", "leak", "trunc", "fire", "spread",
                "tblleak", "hemi");
    std::vector<Row> rows;
    std::FILE* csv = std::fopen(csv_path.c_str(), "w");
    if (!csv) {
        std::fprintf(stderr, "bench_gemmology: cannot write %s\n", csv_path.c_str());
        std::exit(1);
    }
    std::fprintf(csv, "%s\n", kHeader);
    for (double p : pavilions) {
        for (double c : crowns) {
            rows.push_back(measure(p, c, kSweepResolution));
            print_row(rows.back(), stdout, false);
            print_row(rows.back(), csv, true);
            std::fflush(stdout);
        }
    }
    std::fclose(csv);
    return rows;
}

void write_pictures(const char* name, double pavilion, double crown, const fs::path& images,
                    const fs::path& data) {
    FaceUpSettings s;
    s.resolution = kImageResolution;
    s.fire = false;
    const FaceUpAnalysis a = analyse_face_up(brilliant(pavilion, crown), s);
    for (const auto& [suffix, image] :
         {std::pair{"light-return", light_return_image(a)}, std::pair{"aset", aset_image(a)}}) {
        const fs::path path = images / (std::string(name) + "-" + suffix + ".png");
        if (Result<fs::path> w = write_png(image, path); !w) {
            std::fprintf(stderr, "bench_gemmology: %s\n", w.error().c_str());
            std::exit(1);
        }
    }
    // Radial profiles along the pavilion mains' meridians (azimuths k·45°, ±4°), where the
    // meridian geometry of the girdle reflection holds.
    const std::vector<double> mains{0, 45, 90, 135, 180, 225, 270, 315};
    const int bins = 40;
    const std::vector<double> lr = radial_profile(a, bins, &FaceUpPixel::light_return, mains, 4);
    const std::vector<double> girdle = radial_profile(a, bins, &FaceUpPixel::girdle_exit, mains, 4);
    std::ofstream out(data / (std::string(name) + "-radial.csv"));
    out << "radius,light_return,girdle_exit\n";
    for (int i = 0; i < bins; ++i) {
        out << (i + 0.5) / bins << ',' << lr[std::size_t(i)] << ',' << girdle[std::size_t(i)]
            << '\n';
    }
    std::printf("%-10s p = %.2f°, c = %.2f°: LR %.4f, centre (r < 0.15) %.4f, leak %.4f\n", name,
                pavilion, crown, a.totals.light_return, mean_light_return(a, 0.0, 0.15),
                a.totals.leakage);
}

// The gnuplot script names its files relative to the repository root and is run from there,
// so the script written into docs/ can be rerun on any checkout.
void write_charts(const fs::path& root) {
    const std::string data = "docs/gemmology/";
    const std::string images = "docs/images/gemmology/";
    std::ofstream gp(root / images / "charts.gp");
    gp << "# Written by tests/bench/bench_gemmology; run from the repository root.\n"
          "set datafile separator ','\nset terminal pngcairo size 720,480 font 'sans,10'\n"
          "set grid\nset key below\n"
       << "set output '" << images << "pavilion-sweep.png'\n"
       << "set title 'Round brilliant, crown 34.5°, table 53 %: light return against pavilion "
          "angle'\n"
          "set xlabel 'pavilion angle (°)'\nset ylabel 'share of light'\n"
          "set y2label 'fire (° × share of light)'\nset y2tics\nset ytics nomirror\n"
       << "plot '" << data << "pavilion_sweep.csv"
       << "' using 1:3 with linespoints title 'light return to the eye', '' using 1:14 with "
          "linespoints title 'return to the upper hemisphere', '' using 1:9 with linespoints "
          "title 'leakage (below girdle)', '' using 1:8 with linespoints title 'head (blue)', "
          "'' using 1:11 axes x1y2 with linespoints title 'fire (right axis)'\n"
       << "set output '" << images << "crown-sweep.png'\n"
       << "set title 'Round brilliant, pavilion 40.75°, table 53 %: against crown angle'\n"
          "set xlabel 'crown angle (°)'\n"
       << "plot '" << data << "crown_sweep.csv"
       << "' using 2:3 with linespoints title 'light return to the eye', '' using 2:14 with "
          "linespoints title 'return to the upper hemisphere', '' using 2:9 with linespoints "
          "title 'leakage', '' using 2:8 with linespoints title 'head (blue)', '' using 2:11 "
          "axes x1y2 with linespoints title 'fire (right axis)'\n"
       << "set output '" << images << "radial-profiles.png'\n"
       << "set title 'Face-up light return along the pavilion mains'' meridians (±4°)'\n"
          "set xlabel 'radius / girdle radius'\nset ylabel 'light return'\n"
          "set y2label 'weight leaving through the girdle'\n"
       << "plot for [s in 'tolkowsky nailhead fisheye'] '" << data
       << "'.s.'-radial.csv' using 1:2 with lines lw 2 title s, '" << data
       << "fisheye-radial.csv' using 1:3 axes x1y2 with lines dt 2 lw 2 title 'fisheye: "
          "girdle exits (right axis)'\n";
    gp.close();
    const std::string command = "cd '" + root.string() + "' && gnuplot " + images + "charts.gp";
    if (std::system(command.c_str()) != 0) {
        std::fprintf(stderr, "bench_gemmology: gnuplot failed; the charts were not drawn\n");
    }
}

}  // namespace
}  // namespace gem

int main(int argc, char** argv) {
    namespace fs = std::filesystem;
    const fs::path root = argc > 1 ? fs::path(argv[1]) : fs::current_path();
    const fs::path data = root / "docs" / "gemmology";
    const fs::path images = root / "docs" / "images" / "gemmology";
    fs::create_directories(data);
    fs::create_directories(images);
    const auto start = std::chrono::steady_clock::now();

    std::vector<double> pavilions;
    for (double p = 34.0; p <= 48.01; p += 0.5) pavilions.push_back(p);
    std::vector<double> crowns;
    for (double c = 24.0; c <= 42.01; c += 1.0) crowns.push_back(c);
    gem::sweep("Pavilion sweep, crown 34.5°, table 53 %", pavilions, {34.5},
               data / "pavilion_sweep.csv");
    gem::sweep("Crown sweep, pavilion 40.75°, table 53 %", {40.75}, crowns,
               data / "crown_sweep.csv");

    std::printf("\nPictures (%d px)\n", gem::kImageResolution);
    gem::write_pictures("tolkowsky", 40.75, 34.5, images, data);
    gem::write_pictures("nailhead", 45.0, 34.5, images, data);
    gem::write_pictures("fisheye", 36.0, 34.5, images, data);
    gem::write_charts(root);
    const std::chrono::duration<double> took = std::chrono::steady_clock::now() - start;
    std::printf("\n%.1f s\n", took.count());
    return 0;
}
