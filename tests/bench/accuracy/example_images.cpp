#include "example_images.hpp"

#include "picture/image_error.hpp"

namespace gem::accuracy {

Result<bool> write_example(const std::filesystem::path& path, const Image& reference,
                           const std::vector<float>& mask, const std::vector<const Image*>& tests) {
    constexpr int kGap = 4;
    const int w = reference.width;
    const int h = reference.height;
    const int columns = static_cast<int>(tests.size()) + 1;
    Image out(columns * w + (columns - 1) * kGap, 2 * h + kGap, glm::vec4(1.0f));
    auto paste = [&](const Image& image, int column, int row) {
        for (int y = 0; y < h; ++y) {
            for (int x = 0; x < w; ++x) {
                out.at(column * (w + kGap) + x, row * (h + kGap) + y) =
                    glm::vec4(glm::vec3(image.at(x, y)), 1.0f);
            }
        }
    };
    paste(reference, 0, 0);
    // Under the reference: the mask the figures are computed over.
    Image mask_image(w, h);
    for (std::size_t i = 0; i < mask.size(); ++i) mask_image.pixels[i] = glm::vec4(mask[i] * 0.5f);
    paste(mask_image, 0, 1);
    for (std::size_t t = 0; t < tests.size(); ++t) {
        paste(*tests[t], static_cast<int>(t) + 1, 0);
        std::vector<float> de = delta_e_map(*tests[t], reference);
        if (de.size() != mask.size()) return Error{"example image: sizes differ"};
        for (std::size_t i = 0; i < de.size(); ++i) de[i] *= mask[i];
        paste(heat_map(de, w, h, kHeatFullScale), static_cast<int>(t) + 1, 1);
    }
    std::error_code ec;
    std::filesystem::create_directories(path.parent_path(), ec);
    auto written = write_png(out, path);
    if (!written) return Error{written.error()};
    return true;
}

}  // namespace gem::accuracy
