// How far a picture is from its reference over the piece, as the pieces' and the glTF corpus'
// figures are given (docs/gltf.md, docs/pieces.md): both averaged over blocks of N × N pixels
// (linear colour; 4 by default, so that a facet edge a pixel apart is not counted as an error
// twice), then compared as ΔE00 and PSNR (picture/image_error.hpp) over the blocks where the
// mask (gemrender --coverage) covers any pixel.
//
//   compare_pictures TEST.png REFERENCE.png MASK.png [--block N] [--box X0,Y0,X1,Y1]
// --box: only the blocks inside that rectangle of pixels (X1, Y1 excluded), e.g. a ring's
// shank away from its stones. --heat OUT.png: the blocks' ΔE00 as a heat map (0 black .. 20
// white, image_error.hpp), where the two differ.
#include <cstdio>
#include <cstdlib>
#include <string>

#include "picture/image.hpp"
#include "picture/image_error.hpp"

int main(int argc, char** argv) {
    const char* usage =
        "usage: compare_pictures TEST.png REFERENCE.png MASK.png [--block N] "
        "[--box X0,Y0,X1,Y1] [--heat OUT.png]\n";
    if (argc < 4) {
        std::fprintf(stderr, "%s", usage);
        return 2;
    }
    int block = 4;
    int box[4] = {0, 0, 1 << 30, 1 << 30};
    std::string heat;
    for (int i = 4; i < argc; i += 2) {
        const std::string flag = argv[i];
        if (i + 1 >= argc) {
            std::fprintf(stderr, "%s", usage);
            return 2;
        }
        if (flag == "--block") {
            block = std::atoi(argv[i + 1]);
            if (block < 1) {
                std::fprintf(stderr, "compare_pictures: --block takes a whole number of pixels\n");
                return 2;
            }
        } else if (flag == "--heat") {
            heat = argv[i + 1];
        } else if (flag == "--box") {
            if (std::sscanf(argv[i + 1], "%d,%d,%d,%d", &box[0], &box[1], &box[2], &box[3]) != 4) {
                std::fprintf(stderr, "compare_pictures: --box takes X0,Y0,X1,Y1\n");
                return 2;
            }
        } else {
            std::fprintf(stderr, "%s", usage);
            return 2;
        }
    }
    gem::Result<gem::Image> read[3] = {gem::read_png(argv[1]), gem::read_png(argv[2]),
                                       gem::read_png(argv[3])};
    for (const auto& r : read) {
        if (!r) {
            std::fprintf(stderr, "compare_pictures: %s\n", r.error().c_str());
            return 1;
        }
    }
    const gem::Image &test = read[0].value(), &reference = read[1].value(), &mask = read[2].value();
    if (test.width != reference.width || test.height != reference.height ||
        mask.width != reference.width || mask.height != reference.height) {
        std::fprintf(stderr, "compare_pictures: the three pictures differ in size\n");
        return 1;
    }
    const int w = reference.width / block, h = reference.height / block;
    gem::Image a(w, h), b(w, h);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            glm::vec4 sa(0.0f), sb(0.0f);
            bool covered = false;
            for (int j = 0; j < block; ++j) {
                for (int i = 0; i < block; ++i) {
                    sa += test.at(x * block + i, y * block + j);
                    sb += reference.at(x * block + i, y * block + j);
                    const int px = x * block + i, py = y * block + j;
                    const bool inside = px >= box[0] && py >= box[1] && px < box[2] && py < box[3];
                    covered = covered || (inside && mask.at(px, py).x > 0.5f);
                }
            }
            const float n = static_cast<float>(block * block);
            a.at(x, y) = glm::vec4(glm::vec3(sa) / n, covered ? 1.0f : 0.0f);
            b.at(x, y) = glm::vec4(glm::vec3(sb) / n, covered ? 1.0f : 0.0f);
        }
    }
    gem::ErrorOptions options;
    options.only_stone = true;
    auto error = gem::compare_images(a, b, options);
    if (!error) {
        std::fprintf(stderr, "compare_pictures: %s\n", error.error().c_str());
        return 1;
    }
    const gem::ImageError& e = error.value();
    if (!heat.empty()) {
        std::vector<float> delta_e = gem::delta_e_map(a, b);
        for (std::size_t i = 0; i < delta_e.size(); ++i) {
            if (b.pixels[i].w < 0.5f) delta_e[i] = 0.0f;
        }
        auto written = gem::write_png(gem::heat_map(delta_e, w, h, 20.0f), heat);
        if (!written) {
            std::fprintf(stderr, "compare_pictures: %s\n", written.error().c_str());
            return 1;
        }
    }
    std::printf("mean ΔE00 %.2f (p99 %.1f) and %.1f dB over %zu blocks of %d×%d pixels\n",
                e.delta_e_mean, e.delta_e_p99, e.psnr_db, e.pixels, block, block);
    return 0;
}
