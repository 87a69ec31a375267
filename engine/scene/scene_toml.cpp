// Reads a scene from TOML with toml++. Every key is checked against the keys its table knows,
// so a typo is an error rather than a silently ignored setting.
#include <cmath>
#include <fstream>
#include <sstream>

#include <toml++/toml.h>

#include "scene/scene.hpp"
#include "scene/toml_reader.hpp"

namespace gem {

namespace {

using Problem = std::optional<Error>;

Problem read_stone(const Reader& r, const toml::table& t, StoneSource& stone) {
    if (const toml::node* cut = t.get("cut")) {
        std::string name;
        if (auto e = r.string(*cut, "stone.cut", name)) return e;
        const std::optional<CutShape> shape = parse_cut_shape(name);
        if (!shape) return r.error(*cut, "stone.cut", "unknown cut '" + name + "'");
        stone.cut = default_cut_params(*shape);
    }
    CutParams& c = stone.cut;
    for (auto&& [key, node] : t) {
        const std::string k(key.str());
        const std::string full = "stone." + k;
        Problem e;
        if (k == "cut") continue;
        if (k == "model") {
            std::string file;
            e = r.string(node, full, file);
            if (!e) stone.model = r.path(file);
        } else if (k == "model_width_mm") {
            e = r.number_in(node, full, 0.0, 1000.0, stone.model_width_mm);
        } else if (k == "width_mm") {
            e = r.positive(node, full, c.width_mm);
        } else if (k == "length_to_width") {
            e = r.positive(node, full, c.length_to_width);
        } else if (k == "table_pct") {
            e = r.number(node, full, c.table_pct);
        } else if (k == "crown_angle_deg") {
            e = r.number(node, full, c.crown_angle_deg);
        } else if (k == "pavilion_angle_deg") {
            e = r.number(node, full, c.pavilion_angle_deg);
        } else if (k == "girdle_pct") {
            e = r.number(node, full, c.girdle_pct);
        } else if (k == "star_pct") {
            e = r.number(node, full, c.star_pct);
        } else if (k == "lower_girdle_pct") {
            e = r.number(node, full, c.lower_girdle_pct);
        } else if (k == "culet_pct") {
            e = r.number(node, full, c.culet_pct);
        } else if (k == "faceted_girdle") {
            e = r.boolean(node, full, c.faceted_girdle);
        } else {
            e = r.unknown(key, "stone");
        }
        if (e) return e;
    }
    return std::nullopt;
}

Problem read_material(const Reader& r, const toml::table& t, MaterialChoice& m) {
    for (auto&& [key, node] : t) {
        const std::string k(key.str());
        const std::string full = "material." + k;
        Problem e;
        if (k == "name") {
            e = r.string(node, full, m.name);
            if (!e && !find_material(m.name)) {
                e = r.error(node, full, "unknown material '" + m.name + "'");
            }
        } else if (k == "index") {
            double v = 0.0;
            e = r.number_in(node, full, 1.0, 5.0, v);
            m.index = v;
        } else if (k == "dispersion") {
            double v = 0.0;
            e = r.number_in(node, full, 0.0, 1.0, v);
            m.dispersion = v;
        } else if (k == "colour") {
            glm::dvec3 v(1.0);
            e = r.colour(node, full, v);
            m.colour = v;
        } else if (k == "absorption_per_mm") {
            glm::dvec3 v(0.0);
            e = r.colour(node, full, v);
            m.absorption_per_mm = v;
        } else {
            e = r.unknown(key, "material");
        }
        if (e) return e;
    }
    return std::nullopt;
}

Problem read_camera(const Reader& r, const toml::table& t, CameraSettings& c) {
    for (auto&& [key, node] : t) {
        const std::string k(key.str());
        const std::string full = "camera." + k;
        Problem e;
        if (k == "azimuth") {
            e = r.number(node, full, c.azimuth_deg);
        } else if (k == "elevation") {
            e = r.number_in(node, full, -90.0, 90.0, c.elevation_deg);
        } else if (k == "roll") {
            e = r.number(node, full, c.roll_deg);
        } else if (k == "zoom") {
            e = r.positive(node, full, c.zoom);
        } else if (k == "perspective_mm") {
            e = r.number_in(node, full, 0.0, 1e6, c.perspective_distance_mm);
        } else {
            e = r.unknown(key, "camera");
        }
        if (e) return e;
    }
    return std::nullopt;
}

Problem read_environment(const Reader& r, const toml::table& t, EnvironmentChoice& env) {
    for (auto&& [key, node] : t) {
        const std::string k(key.str());
        const std::string full = "environment." + k;
        Problem e;
        if (k == "kind") {
            std::string kind;
            e = r.string(node, full, kind);
            if (e) return e;
            if (kind == "studio") {
                env.kind = EnvironmentChoice::Kind::studio;
            } else if (kind == "uniform") {
                env.kind = EnvironmentChoice::Kind::uniform;
            } else if (kind == "image") {
                env.kind = EnvironmentChoice::Kind::image;
            } else {
                e = r.error(node, full, "expected \"studio\", \"uniform\" or \"image\"");
            }
        } else if (k == "colour") {
            e = r.colour(node, full, env.colour);
        } else if (k == "file") {
            std::string file;
            e = r.string(node, full, file);
            env.file = r.path(file);
        } else if (k == "background") {
            if (node.is_string() && node.value<std::string>() == "environment") {
                env.background_is_environment = true;
            } else if (node.is_array()) {
                env.background_is_environment = false;
                e = r.colour(node, full, env.background_colour);
            } else {
                e = r.error(node, full, "expected \"environment\" or [r, g, b]");
            }
        } else {
            e = r.unknown(key, "environment");
        }
        if (e) return e;
    }
    if (env.kind == EnvironmentChoice::Kind::image && env.file.empty()) {
        return r.error(t, "environment.file", "an image environment needs a file");
    }
    return std::nullopt;
}

Problem read_light(const Reader& r, const toml::table& t, Light& light) {
    bool placed = false;
    for (auto&& [key, node] : t) {
        const std::string k(key.str());
        const std::string full = "light." + k;
        Problem e;
        if (k == "position" || k == "direction") {
            if (placed) return r.error(node, full, "give either position or direction");
            placed = true;
            light.directional = k == "direction";
            e = r.vec3(node, full, light.position);
            if (!e && light.directional && glm::dot(light.position, light.position) == 0.0) {
                e = r.error(node, full, "the direction must not be zero");
            }
        } else if (k == "colour") {
            e = r.colour(node, full, light.colour);
        } else {
            e = r.unknown(key, "light");
        }
        if (e) return e;
    }
    if (!placed) return r.error(t, "light", "needs a position or a direction");
    return std::nullopt;
}

Problem read_shading(const Reader& r, const toml::table& t, Scene& s) {
    for (auto&& [key, node] : t) {
        const std::string k(key.str());
        const std::string full = "shading." + k;
        Problem e;
        if (k == "weights") {
            std::string model;
            e = r.string(node, full, model);
            if (!e && model != "physical" && model != "thesis") {
                e = r.error(node, full, "expected \"physical\" or \"thesis\"");
            }
            s.thesis_weights = model == "thesis";
        } else if (k == "k_s") {
            e = r.number_in(node, full, 0.0, 1e6, s.k_s);
        } else if (k == "k_st") {
            e = r.number_in(node, full, 0.0, 1e6, s.k_st);
        } else if (k == "h") {
            e = r.number_in(node, full, 0.0, 1e6, s.h);
        } else if (k == "alpha") {
            e = r.number_in(node, full, 0.0, 1.0, s.alpha);
        } else if (k == "r_factor") {
            e = r.number_in(node, full, 0.0, 1.0, s.r_factor);
        } else if (k == "t_factor") {
            e = r.number_in(node, full, 0.0, 1.0, s.t_factor);
        } else if (k == "depth") {
            e = r.integer(node, full, 0, 1000, s.depth);
        } else if (k == "min_weight") {
            e = r.number_in(node, full, 0.0, 1.0, s.min_weight);
        } else {
            e = r.unknown(key, "shading");
        }
        if (e) return e;
    }
    return std::nullopt;
}

Problem read_image(const Reader& r, const toml::table& t, Scene& s) {
    for (auto&& [key, node] : t) {
        const std::string k(key.str());
        const std::string full = "image." + k;
        Problem e;
        if (k == "width") {
            e = r.integer(node, full, 1, 16384, s.width);
        } else if (k == "height") {
            e = r.integer(node, full, 1, 16384, s.height);
        } else if (k == "spp") {
            e = r.integer(node, full, 1, 4096, s.samples_per_pixel);
        } else if (k == "spectral") {
            e = r.boolean(node, full, s.spectral);
        } else if (k == "spectral_samples") {
            e = r.integer(node, full, 1, 256, s.spectral_samples);
        } else {
            e = r.unknown(key, "image");
        }
        if (e) return e;
    }
    return std::nullopt;
}

Problem read_document(const Reader& r, const toml::table& doc, Scene& scene) {
    for (auto&& [key, node] : doc) {
        const std::string k(key.str());
        if (k == "light") {
            const toml::array* lights = node.as_array();
            if (lights == nullptr) return r.error(node, "light", "expected [[light]] tables");
            for (const toml::node& entry : *lights) {
                const toml::table* t = entry.as_table();
                if (t == nullptr) return r.error(entry, "light", "expected [[light]] tables");
                if (scene.lights.size() == static_cast<std::size_t>(kMaxLights)) {
                    return r.error(entry, "light",
                                   "at most " + std::to_string(kMaxLights) + " lights");
                }
                Light light;
                if (auto e = read_light(r, *t, light)) return e;
                scene.lights.push_back(light);
            }
            continue;
        }
        const toml::table* t = node.as_table();
        Problem e;
        if (t == nullptr && (k == "stone" || k == "material" || k == "camera" ||
                             k == "environment" || k == "shading" || k == "image")) {
            return r.error(node, k, "expected a table [" + k + "]");
        }
        if (k == "stone") {
            e = read_stone(r, *t, scene.stone);
        } else if (k == "material") {
            e = read_material(r, *t, scene.material);
        } else if (k == "camera") {
            e = read_camera(r, *t, scene.camera);
        } else if (k == "environment") {
            e = read_environment(r, *t, scene.environment);
        } else if (k == "shading") {
            e = read_shading(r, *t, scene);
        } else if (k == "image") {
            e = read_image(r, *t, scene);
        } else {
            e = r.unknown(key, "");
        }
        if (e) return e;
    }
    return std::nullopt;
}

}  // namespace

Result<Scene> parse_scene(std::string_view text, const std::string& name,
                          const std::filesystem::path& base) {
    Result<toml::table> parsed = parse_toml(text, name);
    if (!parsed) return Error{parsed.error()};
    const toml::table& doc = parsed.value();
    Scene scene = default_scene();
    // A file's lights replace the default ones rather than adding to them.
    if (doc.contains("light")) scene.lights.clear();
    const Reader reader(name, base);
    if (auto e = read_document(reader, doc, scene)) return *e;
    return scene;
}

Result<Scene> load_scene(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return Error{"cannot read " + path.string() + ": cannot open the file"};
    std::ostringstream text;
    text << in.rdbuf();
    return parse_scene(text.str(), path.string(), path.parent_path());
}

}  // namespace gem
