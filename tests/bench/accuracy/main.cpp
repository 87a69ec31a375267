// bench_accuracy: the speed-against-accuracy sweep of the shading methods (docs/accuracy.md).
//
//   bench_accuracy [--quick] [--csv FILE] [--images DIR] [--cache DIR] [--charts DIR]
//
// --quick   a smoke run (< 1 min): the face-up diamond, 128 px, a few settings
// --csv     where the rows go (default accuracy.csv in the working directory)
// --images  where the example pictures go (default: none)
// --cache   built databases are kept here (default: the build tree), so a re-run only renders
// --charts  runs gnuplot on charts.gp to draw the charts into DIR (needs gnuplot)
#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "gpu/egl_context.hpp"
#include "sweep.hpp"

int main(int argc, char** argv) {
    gem::accuracy::SweepOptions options;
    options.cache = GEM_ACCURACY_CACHE_DIR;
    std::string csv = "accuracy.csv";
    std::string charts;
    std::string images;
    std::string cache = options.cache.string();
    CLI::App app{"bench_accuracy: the speed-against-accuracy sweep (docs/accuracy.md)"};
    app.add_flag("--quick", options.quick, "a smoke run: the face-up diamond, 128 px");
    app.add_option("--csv", csv, "where the rows go")->capture_default_str();
    app.add_option("--images", images, "where the example pictures go (default: none)");
    app.add_option("--cache", cache, "built databases are kept here")->capture_default_str();
    app.add_option("--charts", charts, "draw the charts here with gnuplot");
    CLI11_PARSE(app, argc, argv);
    options.cache = cache;
    if (!images.empty()) options.images = images;
    if (options.quick) {
        options.image = 128;
        options.frames = 2;
    }
    auto context = gem::gpu::EglContext::headless();
    if (!context) {
        std::fprintf(stderr, "bench_accuracy: %s\n", context.error().c_str());
        return 1;
    }
    std::printf("GL: %s; frames %d×%d px, databases cached in %s\n",
                context.value().description().c_str(), options.image, options.image,
                options.cache.c_str());
    const auto start = std::chrono::steady_clock::now();
    auto rows = gem::accuracy::run_sweep(options);
    if (!rows) {
        std::fprintf(stderr, "bench_accuracy: %s\n", rows.error().c_str());
        return 1;
    }
    auto written = gem::accuracy::write_csv(rows.value(), csv);
    if (!written) {
        std::fprintf(stderr, "bench_accuracy: %s\n", written.error().c_str());
        return 1;
    }
    std::printf("%zu rows → %s in %.0f s\n", rows.value().size(), csv.c_str(),
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    if (!charts.empty()) {
        std::filesystem::create_directories(charts);
        const std::string scenes =
            options.quick ? "; sweep_scene='diamond-faceup'; path_scenes='diamond-faceup'; "
                            "still_scenes='diamond-faceup'"
                          : "";
        const std::string command = "gnuplot -e \"csv='" + csv + "'; out='" + charts + "'" +
                                    scenes + "\" " + GEM_ACCURACY_CHARTS;
        if (std::system(command.c_str()) != 0) {
            std::fprintf(stderr, "bench_accuracy: gnuplot failed: %s\n", command.c_str());
            return 1;
        }
        std::printf("charts → %s\n", charts.c_str());
    }
    return 0;
}
