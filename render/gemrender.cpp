// gemrender: renders a stone or a piece to a PNG, with the exact CPU tracer (--method reference,
// the default; optionally also a linear PFM) or headless on the GPU through EGL (--method table,
// trace or phong; gpu_render.hpp). Options override the scene file; with no arguments at all
// it renders the built-in default scene to out/gemrender-default.png.
#include <cstdio>
#include <filesystem>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cpu/reference_render.hpp"
#include "cpu/scene_settings.hpp"
#include "gpu/stone_method.hpp"
#include "gpu_render.hpp"
#include "picture/image.hpp"
#include "picture/tone_map.hpp"
#include "piece/piece_file.hpp"
#include "scene/scene.hpp"
#include "scene/scene_build.hpp"

namespace {

struct Options {
    std::string scene;
    std::string cut;
    std::string model;
    std::string material;
    double azimuth = 0.0;
    double elevation = 0.0;
    double roll = 0.0;
    double zoom = 1.0;
    int size = 0;
    int spp = 0;
    double perspective = 0.0;
    std::string environment;
    std::vector<std::string> lights;
    std::string weights;
    int depth = 0;
    bool spectral = false;
    std::string out;
    std::string linear;
    std::string coverage;
    std::string method = "reference";
    std::string piece;
    bool metal_sees_environment = false;
    std::string tone = "neutral";
    double exposure_ev = 0.0;
    gem::GpuRenderOptions gpu;
};

int fail(const std::string& message) {
    std::fprintf(stderr, "gemrender: %s\n", message.c_str());
    return 1;
}

// "x,y,z,r,g,b": a point light's position (mm) and linear RGB colour.
gem::Result<gem::Light> parse_light(const std::string& text) {
    std::vector<double> v;
    std::stringstream in(text);
    std::string item;
    while (std::getline(in, item, ',')) {
        try {
            std::size_t used = 0;
            v.push_back(std::stod(item, &used));
            if (used != item.size()) throw std::invalid_argument(item);
        } catch (const std::exception&) {
            return gem::Error{"--light " + text + ": '" + item + "' is not a number"};
        }
    }
    if (v.size() != 6) return gem::Error{"--light " + text + ": expected x,y,z,r,g,b"};
    if (v[3] < 0 || v[4] < 0 || v[5] < 0) {
        return gem::Error{"--light " + text + ": the colour must not be negative"};
    }
    gem::Light light;
    light.position = {v[0], v[1], v[2]};
    light.colour = {v[3], v[4], v[5]};
    return light;
}

// Applies the options that were given on top of the scene.
gem::Result<gem::Scene> apply(const CLI::App& app, const Options& o, gem::Scene scene) {
    auto given = [&](const char* name) { return app.count(name) > 0; };
    if (given("--cut")) {
        const auto shape = gem::parse_cut_shape(o.cut);
        if (!shape) return gem::Error{"--cut: unknown cut '" + o.cut + "'"};
        scene.stone.cut = gem::default_cut_params(*shape);
        scene.stone.model.clear();
    }
    if (given("--model")) scene.stone.model = o.model;
    if (given("--material")) {
        if (!gem::find_material(o.material)) {
            return gem::Error{"--material: unknown material '" + o.material + "'"};
        }
        scene.material = gem::MaterialChoice{};
        scene.material.name = o.material;
    }
    if (given("--azimuth")) scene.camera.azimuth_deg = o.azimuth;
    if (given("--elevation")) scene.camera.elevation_deg = o.elevation;
    if (given("--roll")) scene.camera.roll_deg = o.roll;
    if (given("--zoom")) scene.camera.zoom = o.zoom;
    if (given("--size")) scene.width = scene.height = o.size;
    if (given("--spp")) scene.samples_per_pixel = o.spp;
    if (given("--perspective")) scene.camera.perspective_distance_mm = o.perspective;
    if (given("--environment")) {
        if (o.environment == "studio") {
            scene.environment.kind = gem::EnvironmentChoice::Kind::studio;
        } else {
            scene.environment.kind = gem::EnvironmentChoice::Kind::image;
            scene.environment.file = o.environment;
        }
    }
    if (given("--light")) {
        if (o.lights.size() > static_cast<std::size_t>(gem::kMaxLights)) {
            return gem::Error{"--light: at most " + std::to_string(gem::kMaxLights) + " lights"};
        }
        scene.lights.clear();
        for (const std::string& text : o.lights) {
            gem::Result<gem::Light> light = parse_light(text);
            if (!light) return gem::Error{light.error()};
            scene.lights.push_back(light.value());
        }
    }
    if (given("--weights")) scene.thesis_weights = o.weights == "thesis";
    if (given("--depth")) scene.depth = o.depth;
    if (given("--spectral")) scene.spectral = true;
    return scene;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"Renders a faceted gemstone: exact CPU tracer or GPU shading stage."};
    Options o;
    app.add_option("--scene", o.scene, "scene file (TOML, see config/scenes/README.md)")
        ->check(CLI::ExistingFile);
    app.add_option("--cut", o.cut, "parametric cut: round, princess, emerald, oval, ...");
    app.add_option("--model", o.model, "model file (GemCad .asc, OBJ, STL)")
        ->check(CLI::ExistingFile);
    app.add_option("--material", o.material, "built-in material, e.g. diamond, sapphire");
    app.add_option("--azimuth", o.azimuth, "view azimuth in degrees");
    app.add_option("--elevation", o.elevation, "view elevation in degrees (90 = face-up)")
        ->check(CLI::Range(-90.0, 90.0));
    app.add_option("--roll", o.roll, "roll about the view axis in degrees");
    app.add_option("--zoom", o.zoom, "zoom (1 = the stone fills the image)")
        ->check(CLI::PositiveNumber);
    app.add_option("--size", o.size, "image width and height in pixels")
        ->check(CLI::Range(1, 16384));
    app.add_option("--spp", o.spp, "samples per pixel")->check(CLI::Range(1, 4096));
    app.add_option("--perspective", o.perspective, "perspective camera at this distance (mm)")
        ->check(CLI::PositiveNumber);
    app.add_option("--environment", o.environment, "studio, or an equirectangular PNG/HDR");
    app.add_option("--light", o.lights, "point light x,y,z,r,g,b (repeat for up to 4)");
    app.add_option("--weights", o.weights, "physical or thesis")
        ->check(CLI::IsMember({"physical", "thesis"}));
    app.add_option("--depth", o.depth, "internal ray segments followed")
        ->check(CLI::Range(0, 1000));
    app.add_flag("--spectral", o.spectral, "trace wavelength samples (dispersion)");
    app.add_option("--out", o.out, "PNG to write (8-bit sRGB)");
    app.add_option("--linear", o.linear, "also write linear float colour as PFM (reference)");
    app.add_option("--coverage", o.coverage,
                   "also write where the stone or piece covers a pixel, as a white-on-black PNG "
                   "(reference; what compare_pictures measures over)");
    app.add_flag("--metal-sees-environment", o.metal_sees_environment,
                 "reference, --piece: the metal's reflections see the environment and the lights "
                 "only, as the GPU's metal does (what the metal's view of the piece changes)");
    app.add_option("--piece", o.piece,
                   "a piece description (config/pieces/README.md) instead of a stone")
        ->check(CLI::ExistingFile);
    // The CPU's exact reference, or a GPU stone method by its registry name.
    std::vector<std::string> methods = {"reference"};
    for (const gem::gpu::MethodEntry* m : gem::gpu::stone_methods()) methods.emplace_back(m->name);
    app.add_option(
           "--method", o.method,
           "reference (CPU, exact) or a GPU stone method (" + gem::gpu::stone_method_names() + ")")
        ->check(CLI::IsMember(methods));
    app.add_option("--db", o.gpu.databases,
                   "ray-table database for --method table; with --piece (repeatable), tables "
                   "for its stones of that kind (gemtables build --width-mm W --min-elevation -90)")
        ->check(CLI::ExistingFile);
    app.add_flag("--blend", o.gpu.blend, "table: blend the two nearest stored views");
    app.add_option("--fire", o.gpu.fire,
                   "trace: dispersion none, first (first order, as tables), exact (per channel) "
                   "or spectral (each still frame its own wavelengths; exact while moving)")
        ->check(CLI::IsMember({"none", "first", "exact", "spectral"}));
    app.add_option("--ring", o.gpu.ring, "GPU: 'parametric' or a ring OBJ in the stone frame");
    app.add_option("--metal", o.gpu.metal, "ring metal: yellow_gold, white_gold, platinum, silver");
    app.add_option("--frames", o.gpu.frames, "GPU: a turntable of N frames, timed")
        ->check(CLI::Range(1, 100000));
    app.add_option("--turn", o.gpu.turn_deg, "turntable azimuth step per frame, degrees");
    app.add_option("--frames-dir", o.gpu.frames_dir, "write every turntable frame here");
    app.add_option("--tone", o.tone, "tone curve before the sRGB encoding: neutral or clip")
        ->check(CLI::IsMember({"neutral", "clip"}));
    app.add_option("--exposure", o.exposure_ev, "exposure in stops before the tone curve");
    app.add_option("--msaa", o.gpu.msaa, "GPU: samples per pixel of the rasterised geometry")
        ->check(CLI::Range(1, 16));
    app.add_option("--glare", o.gpu.glare, "GPU: share of the picture spread as glare (0: none)")
        ->check(CLI::Range(0.0, 1.0));
    app.add_option("--still-frames", o.gpu.still_frames,
                   "GPU, one picture: average this many frames a sub-pixel apart")
        ->check(CLI::Range(1, 1024));
    app.add_option("--still-depth", o.gpu.still_depth,
                   "trace: the depth those frames follow where deeper than --depth")
        ->check(CLI::Range(0, 64));
    app.add_option("--still-depth-max", o.gpu.still_depth_max,
                   "trace: those frames deeper as they accumulate, to this (the kiosk's "
                   "picture.still_depth_max)")
        ->check(CLI::Range(0, 64));
    CLI11_PARSE(app, argc, argv);
    o.gpu.display.curve = *gem::tone_curve_named(o.tone);
    o.gpu.display.exposure_ev = o.exposure_ev;

    const bool defaults_only = argc == 1;
    if (defaults_only) {
        o.out = "out/gemrender-default.png";
        std::error_code ec;
        std::filesystem::create_directories("out", ec);
        if (ec) return fail("cannot create out/: " + ec.message());
    } else if (o.out.empty()) {
        return fail("--out FILE.png is required (run without arguments for the default scene)");
    }

    gem::Scene scene = gem::default_scene();
    if (!o.scene.empty()) {
        gem::Result<gem::Scene> loaded = gem::load_scene(o.scene);
        if (!loaded) return fail(loaded.error());
        scene = std::move(loaded).value();
    }
    gem::Result<gem::Scene> final_scene = apply(app, o, std::move(scene));
    if (!final_scene) return fail(final_scene.error());
    const gem::Scene& s = final_scene.value();
    std::optional<gem::Piece> piece;
    if (!o.piece.empty()) {
        std::vector<std::string> lines;
        gem::Result<gem::Piece> loaded = gem::load_piece(o.piece, &lines);
        if (!loaded) return fail(loaded.error());
        piece = std::move(loaded).value();
        for (const std::string& line : lines) std::printf("gemrender: %s\n", line.c_str());
        std::printf("gemrender: %s\n", gem::describe(*piece).c_str());
        o.gpu.piece = &*piece;
    }
    if (o.method != "reference") {
        o.gpu.method = o.method;
        o.gpu.out = o.out;
        return gem::render_gpu(s, o.gpu);
    }

    gem::Result<gem::Environment> environment = gem::build_environment(s);
    if (!environment) return fail(environment.error());
    gem::RenderStats stats;
    gem::Result<gem::Image> image = gem::Error{""};
    if (piece) {
        image = gem::render_piece_reference(
            *piece, environment.value(), gem::render_settings(s), &stats,
            o.metal_sees_environment ? gem::PieceSight::metal_sees_environment
                                     : gem::PieceSight::everything);
    } else {
        gem::Result<gem::Stone> stone = gem::build_stone(s);
        if (!stone) return fail(stone.error());
        image = gem::render_reference(stone.value(), environment.value(), gem::render_settings(s),
                                      &stats);
    }
    if (!image) return fail(image.error());
    if (auto written = gem::write_png(gem::to_display(image.value(), o.gpu.display), o.out);
        !written) {
        return fail(written.error());
    }
    if (!o.linear.empty()) {
        if (auto written = gem::write_pfm(image.value(), o.linear); !written) {
            return fail(written.error());
        }
    }
    if (!o.coverage.empty()) {
        gem::Image mask = image.value();
        for (glm::vec4& p : mask.pixels) p = glm::vec4(glm::vec3(p.w > 0.5f ? 1.0f : 0.0f), 1.0f);
        if (auto written = gem::write_png(mask, o.coverage); !written) {
            return fail(written.error());
        }
    }
    const std::filesystem::path shown = std::filesystem::absolute(o.out);
    std::printf("gemrender: wrote %s (%d×%d, %d spp%s) in %.2f s, %.2f M rays/s\n", shown.c_str(),
                s.width, s.height, s.samples_per_pixel, s.spectral ? ", spectral" : "",
                stats.seconds, stats.seconds > 0 ? stats.pixel_rays / stats.seconds * 1e-6 : 0.0);
    if (!o.linear.empty()) std::printf("gemrender: wrote %s\n", o.linear.c_str());
    return 0;
}
