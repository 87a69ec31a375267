// GemCad text designs (.asc): a faceting machine's settings, one tier of facets per "a" line.
//
//   GemCad 5.0            the program and its version (GemCad 4 writes "GemCad 4.x")
//   g 96 0.0              index gear (signed teeth) and its offset (an index)
//   y 8 y                 symmetry fold and mirror flag
//   I 1.54                refractive index the design was optimised for
//   H text / F text       header and footnote text
//   a -42.5 0.618 93 n 1 87 81 ...   angle, distance, then indices with "n <name>" labels
//
// The index gear, as GemCad's manual defines it (GemCad User's Manual 4.51, R. W. Strickland,
// "Index gear (g)"): gears with a positive number of teeth number their indices counter-
// clockwise in the Top View, negative ones clockwise; the offset is the index shown at the
// bottom of the Top View (0: index 0 at the bottom; half the teeth: at the top). Some writers
// leave out the "g" and start that line with the teeth.
// Conventions chosen here for the stone frame (y up through the table):
// - The Top View is the stone seen from +y with +z at the bottom of the picture (the camera's
//   face-up view, picture/camera.hpp: right +x, up -z). So index i lies at azimuth
//   θ = sign(teeth)·2π·(i − offset)/|teeth|, measured from +z toward +x: counter-clockwise
//   seen from above, as GemCad draws a positive gear.
// - Angle a: inclination of the facet from the girdle plane; a > 0 crown, a < 0 pavilion,
//   0 table, ±90 girdle. Outward normal n = (sin|a|·sin θ, ±cos a, sin|a|·cos θ), + on the
//   crown side; the facet plane is n·x = distance. A culet (horizontal pavilion facet) is
//   written "-0" or as angle 0 with a negative distance.
// - A name after "n" labels the index just before it and the indices after it, up to the next
//   name; indices before the first name share it. A "G" token starts free-text cutting notes.
// - Long tiers may continue on lines that start with an index, "n" or "G".
// - Mirror symmetry maps index i to −i (the machine's mirror), whatever the offset. Symmetry
//   the facets do not actually have is dropped.
// Read: the GemCad line, g, y, I, the first H (the design's name) and a. Passed over: further H
// lines and F lines (text for the cutter). Anything else is an error naming the line.

#include <cctype>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>

#include "geometry/polyhedron.hpp"
#include "geometry/validate.hpp"
#include "import/default_material.hpp"
#include "import/import_text.hpp"
#include "import/load_model.hpp"

namespace gem {
namespace {

struct Tier {
    double angle_deg = 0.0;
    double distance = 0.0;
    std::vector<double> indices;
    std::vector<std::string> names;  // one per index
    std::size_t line = 0;
    bool notes = false;                // a "G" token was seen: the rest is free text
    std::optional<std::string> label;  // the tier's first name, for indices written before it
};

struct Design {
    int gear = 96;        // signed: negative gears number their indices clockwise
    double offset = 0.0;  // the index at the bottom of the Top View
    int fold = 1;
    bool mirror = false;
    std::optional<Material> material;
    std::string title;
    std::vector<Tier> tiers;
};

class GemcadParser {
  public:
    explicit GemcadParser(const std::filesystem::path& path) : path_(path) {}

    Result<Design> parse(std::string_view text) {
        import::LineCursor cursor(text);
        std::string_view line;
        if (!cursor.next(line) || !import::istarts_with(line, "GemCad")) {
            return import::line_error(path_, 1,
                                      "not a GemCad design (the first line must be "
                                      "'GemCad <version>')");
        }
        while (cursor.next(line)) {
            line_ = cursor.line_number();
            if (auto problem = parse_line(line)) return *problem;
        }
        for (Tier& tier : design_.tiers) {
            // Indices before the tier's first label take that label.
            const std::string first = tier.label.value_or("");
            for (auto& n : tier.names) {
                if (n.empty()) n = first;
            }
        }
        if (design_.tiers.empty())
            return import::file_error(path_, "design has no tiers ('a' lines)");
        return design_;
    }

  private:
    Error error(const std::string& message) const {
        return import::line_error(path_, line_, message);
    }

    std::optional<Error> parse_line(std::string_view line) {
        auto tokens = import::split_tokens(line);
        if (tokens.empty()) return std::nullopt;
        // Some writers glue the keyword to its first value ("g96 0.0").
        const std::string_view first = tokens[0];
        if (first.size() > 1 && std::string_view("gyIa").find(first[0]) != std::string_view::npos &&
            (std::isdigit(static_cast<unsigned char>(first[1])) || first[1] == '-' ||
             first[1] == '.')) {
            tokens[0] = first.substr(1);
            tokens.insert(tokens.begin(), first.substr(0, 1));
        }
        // The gear line without its letter: "96 0.0" before any tier.
        if (!gear_seen_ && design_.tiers.empty() && tokens.size() <= 2 &&
            import::parse_integer(tokens[0]) &&
            (tokens.size() == 1 || import::parse_number(tokens[1]))) {
            tokens.insert(tokens.begin(), "g");
        }
        const std::string_view k = tokens[0];
        const std::string_view rest = line.substr(line.find(k) + k.size());
        const bool tier_was_open = tier_open_;
        tier_open_ = k == "a";
        if (k == "H") {
            if (design_.title.empty()) design_.title = trimmed(rest);
            return std::nullopt;
        }
        if (k == "F") return std::nullopt;
        if (k == "g") return parse_gear(tokens);
        if (k == "y") return parse_symmetry(tokens);
        if (k == "I") return parse_index(tokens);
        if (k == "a") return parse_tier(tokens);
        const bool continues = tier_was_open && !design_.tiers.back().notes &&
                               (k == "n" || k == "G" || import::parse_number(k).has_value());
        if (continues) {
            tier_open_ = true;
            return add_tier_tokens(design_.tiers.back(), tokens, 0);
        }
        return error("unknown line '" + std::string(k) + "'");
    }

    static std::string trimmed(std::string_view s) {
        const auto b = s.find_first_not_of(" \t");
        if (b == std::string_view::npos) return {};
        const auto e = s.find_last_not_of(" \t");
        return std::string(s.substr(b, e - b + 1));
    }

    std::optional<double> number(std::string_view token, const char* what, Error& out) const {
        auto v = import::parse_number(token);
        if (!v) out = error(std::string(what) + " '" + std::string(token) + "' is not a number");
        return v;
    }

    std::optional<Error> parse_gear(const std::vector<std::string_view>& t) {
        if (t.size() < 2) return error("gear line needs 'g <teeth> <offset>'");
        if (gear_seen_) return error("a second gear line");
        const auto teeth = import::parse_integer(t[1]);
        if (!teeth || *teeth == 0 || *teeth > 100000 || *teeth < -100000) {
            return error("gear '" + std::string(t[1]) +
                         "' is not a whole number of teeth (1 to 100000, negative: clockwise)");
        }
        design_.gear = static_cast<int>(*teeth);
        gear_seen_ = true;
        if (t.size() > 2) {
            Error e;
            const auto offset = number(t[2], "gear offset", e);
            if (!offset) return e;
            if (std::abs(*offset) > 100000.0) {
                return error("gear offset " + std::string(t[2]) + " is not an index of the gear");
            }
            design_.offset = *offset;
        }
        return std::nullopt;
    }

    std::optional<Error> parse_symmetry(const std::vector<std::string_view>& t) {
        if (t.size() < 3) return error("symmetry line needs 'y <fold> <y|n>'");
        const auto fold = import::parse_integer(t[1]);
        if (!fold || *fold <= 0 || *fold > 1000) {
            return error("symmetry fold '" + std::string(t[1]) +
                         "' is not a positive whole number");
        }
        if (t[2] != "y" && t[2] != "n") {
            return error("symmetry mirror flag '" + std::string(t[2]) + "' is not 'y' or 'n'");
        }
        design_.fold = static_cast<int>(*fold);
        design_.mirror = t[2] == "y";
        return std::nullopt;
    }

    std::optional<Error> parse_index(const std::vector<std::string_view>& t) {
        if (t.size() < 2) return error("index line needs 'I <refractive index>'");
        Error e;
        const auto n = number(t[1], "refractive index", e);
        if (!n) return e;
        if (*n < 1.0) return error("refractive index " + std::string(t[1]) + " is below 1");
        design_.material = import::gemcad_index_material(*n, std::string(t[1]));
        return std::nullopt;
    }

    std::optional<Error> parse_tier(const std::vector<std::string_view>& t) {
        if (t.size() < 3) return error("tier line needs 'a <angle> <distance> <indices...>'");
        Error e;
        const auto angle = number(t[1], "tier angle", e);
        if (!angle) return e;
        const auto distance = number(t[2], "tier distance", e);
        if (!distance) return e;
        if (std::abs(*angle) > 90.0) {
            return error("tier angle " + std::string(t[1]) + " is outside -90..90 degrees");
        }
        Tier tier;
        tier.line = line_;
        tier.angle_deg = *angle;
        tier.distance = *distance;
        // The culet's alternative spelling: angle 0 with a negative distance.
        if (*angle == 0.0 && *distance < 0.0) {
            tier.angle_deg = -0.0;
            tier.distance = -*distance;
        }
        if (!(tier.distance > 0.0)) {
            return error("tier distance " + std::string(t[2]) + " is not positive");
        }
        design_.tiers.push_back(std::move(tier));
        return add_tier_tokens(design_.tiers.back(), t, 3);
    }

    std::optional<Error> add_tier_tokens(Tier& tier, const std::vector<std::string_view>& t,
                                         std::size_t from) {
        for (std::size_t i = from; i < t.size() && !tier.notes; ++i) {
            if (t[i] == "G") {
                tier.notes = true;
            } else if (t[i] == "n") {
                if (i + 1 >= t.size()) return error("tier name missing after 'n'");
                const std::string name(t[++i]);
                if (!tier.label) tier.label = name;
                if (!tier.names.empty()) tier.names.back() = name;
            } else {
                Error e;
                const auto index = number(t[i], "tier index", e);
                if (!index) return e;
                tier.indices.push_back(*index);
                tier.names.push_back(tier.names.empty() ? "" : tier.names.back());
            }
        }
        return std::nullopt;
    }

    std::filesystem::path path_;
    std::size_t line_ = 1;
    Design design_;
    bool tier_open_ = false;  // the previous line was a tier or its continuation
    bool gear_seen_ = false;
};

FacetKind kind_of(double angle_deg) {
    if (std::abs(angle_deg) == 90.0) return FacetKind::girdle;
    if (angle_deg == 0.0) return std::signbit(angle_deg) ? FacetKind::culet : FacetKind::table;
    return angle_deg > 0.0 ? FacetKind::crown : FacetKind::pavilion;
}

glm::dmat3 rotation_about_y(double angle) {
    // Turns azimuth θ (from +z toward +x) into θ + angle; glm matrices are column-major.
    const double c = std::cos(angle), s = std::sin(angle);
    return glm::dmat3(glm::dvec3(c, 0.0, -s), glm::dvec3(0.0, 1.0, 0.0), glm::dvec3(s, 0.0, c));
}

glm::dmat3 mirror_about_azimuth(double theta0) {
    // Reflects azimuth θ to 2·θ0 − θ, keeping y: the reflection about (sin θ0, 0, cos θ0).
    const double c = std::cos(2.0 * theta0), s = std::sin(2.0 * theta0);
    return glm::dmat3(glm::dvec3(-c, 0.0, s), glm::dvec3(0.0, 1.0, 0.0), glm::dvec3(s, 0.0, c));
}

}  // namespace

Result<Stone> load_gemcad(const std::filesystem::path& path) {
    auto bytes = import::read_whole_file(path);
    if (!bytes) return Error{bytes.error()};
    return parse_gemcad(bytes.value(), path);
}

Result<Stone> parse_gemcad(std::string_view text, const std::filesystem::path& path) {
    if (text.empty()) return import::file_error(path, "empty file");
    auto parsed = GemcadParser(path).parse(text);
    if (!parsed) return Error{parsed.error()};
    const Design& design = parsed.value();

    // Azimuth of index i, from +z toward +x (see the top of the file).
    const double turn = (design.gear > 0 ? 2.0 : -2.0) * std::numbers::pi / std::abs(design.gear);
    const auto azimuth = [&](double index) { return turn * (index - design.offset); };
    std::vector<FacetPlane> planes;
    for (const Tier& tier : design.tiers) {
        const FacetKind kind = kind_of(tier.angle_deg);
        const double a = std::abs(tier.angle_deg) * std::numbers::pi / 180.0;
        const double up = (std::signbit(tier.angle_deg) ? -1.0 : 1.0) * std::cos(a);
        if (tier.indices.empty() && !(kind == FacetKind::table || kind == FacetKind::culet)) {
            return import::line_error(path, tier.line, "tier has no index");
        }
        // A horizontal tier is one plane whatever indices it lists.
        const std::size_t count =
            (kind == FacetKind::table || kind == FacetKind::culet) ? 1 : tier.indices.size();
        for (std::size_t i = 0; i < count; ++i) {
            const double theta = azimuth(tier.indices.empty() ? 0.0 : tier.indices[i]);
            FacetPlane fp;
            fp.plane.n = glm::normalize(
                glm::dvec3(std::sin(a) * std::sin(theta), up, std::sin(a) * std::cos(theta)));
            fp.plane.d = tier.distance;
            fp.kind = kind;
            fp.name = tier.names.empty() ? std::string() : tier.names[i];
            planes.push_back(std::move(fp));
        }
    }
    const std::string name = design.title.empty() ? path.stem().string() : design.title;
    auto stone = stone_from_planes(planes, name);
    if (!stone) return import::file_error(path, stone.error());

    Stone& s = stone.value();
    s.symmetry.clear();
    for (int k = 0; k < design.fold; ++k) {
        s.symmetry.push_back(rotation_about_y(2.0 * std::numbers::pi * k / design.fold));
    }
    if (design.mirror) {
        const glm::dmat3 m = mirror_about_azimuth(azimuth(0.0));
        for (int k = 0; k < design.fold; ++k) s.symmetry.push_back(s.symmetry[std::size_t(k)] * m);
    }
    // Some designs claim more symmetry than their facets have (a tilted table, one odd
    // facet). Tables folded by a false symmetry would show the wrong stone, so only the
    // elements that map the stone onto itself are kept; those form a group again.
    std::vector<glm::dmat3> claimed = std::move(s.symmetry);
    s.symmetry.clear();
    for (const glm::dmat3& g : claimed) {
        Stone probe;
        probe.vertices = s.vertices;
        probe.symmetry = {g};
        if (s.symmetry.empty() || symmetry_holds(probe)) s.symmetry.push_back(g);
    }
    s.material = design.material.value_or(import::crown_glass());
    return stone;
}

}  // namespace gem
