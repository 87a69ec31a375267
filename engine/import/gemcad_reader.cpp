// GemCad text designs (.asc): a faceting machine's settings, one tier of facets per "a" line.
//
//   GemCad 5.0            header and program version
//   g 96 0.0              index gear (teeth) and reference angle
//   y 8 y                 symmetry fold and mirror flag
//   I 1.54                refractive index the design was optimised for
//   H text / F text       header and footnote text
//   a -42.5 0.618 93 n 1 87 81 ...   angle, distance, then indices with "n <name>" labels
//
// Conventions chosen here (the file format leaves them to the program):
// - Azimuth of index i: φ = 2π·i/gear + reference angle (read as degrees), measured from +x
//   toward +z, i.e. clockwise seen from above (from +y) in the right-handed stone frame.
// - Angle a: inclination of the facet from the girdle plane; a > 0 crown, a < 0 pavilion,
//   0 table, ±90 girdle. Outward normal n = (sin|a|·cos φ, ±cos a, sin|a|·sin φ), + on the
//   crown side; the facet plane is n·x = distance. A culet (horizontal pavilion facet) is
//   written "-0" or as angle 0 with a negative distance.
// - A name after "n" labels the index just before it and the indices after it, up to the next
//   name; indices before the first name share it. A "G" token starts free-text cutting notes.
// - Long tiers may continue on lines that start with an index, "n" or "G".
// - Mirror symmetry maps index i to −i, i.e. reflects about the azimuth of index 0. Symmetry
//   the facets do not actually have is dropped.

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
    int gear = 96;
    double reference_deg = 0.0;
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
        if (t.size() < 2) return error("gear line needs 'g <teeth> <reference angle>'");
        const auto teeth = import::parse_integer(t[1]);
        if (!teeth || *teeth <= 0 || *teeth > 100000) {
            return error("gear '" + std::string(t[1]) + "' is not a positive whole number");
        }
        design_.gear = static_cast<int>(*teeth);
        if (t.size() > 2) {
            Error e;
            const auto ref = number(t[2], "gear reference angle", e);
            if (!ref) return e;
            design_.reference_deg = *ref;
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
};

FacetKind kind_of(double angle_deg) {
    if (std::abs(angle_deg) == 90.0) return FacetKind::girdle;
    if (angle_deg == 0.0) return std::signbit(angle_deg) ? FacetKind::culet : FacetKind::table;
    return angle_deg > 0.0 ? FacetKind::crown : FacetKind::pavilion;
}

glm::dmat3 rotation_about_y(double phi) {
    // Turns azimuth φ (from +x toward +z) into φ + phi; glm matrices are column-major.
    const double c = std::cos(phi), s = std::sin(phi);
    return glm::dmat3(glm::dvec3(c, 0.0, s), glm::dvec3(0.0, 1.0, 0.0), glm::dvec3(-s, 0.0, c));
}

glm::dmat3 mirror_about_azimuth(double phi0) {
    // Reflects azimuth φ to 2·phi0 − φ, keeping y.
    const double c = std::cos(2.0 * phi0), s = std::sin(2.0 * phi0);
    return glm::dmat3(glm::dvec3(c, 0.0, s), glm::dvec3(0.0, 1.0, 0.0), glm::dvec3(s, 0.0, -c));
}

}  // namespace

Result<Stone> load_gemcad(const std::filesystem::path& path) {
    auto bytes = import::read_whole_file(path);
    if (!bytes) return Error{bytes.error()};
    if (bytes.value().empty()) return import::file_error(path, "empty file");
    auto parsed = GemcadParser(path).parse(bytes.value());
    if (!parsed) return Error{parsed.error()};
    const Design& design = parsed.value();

    const double reference = design.reference_deg * std::numbers::pi / 180.0;
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
            const double index = tier.indices.empty() ? 0.0 : tier.indices[i];
            const double phi = 2.0 * std::numbers::pi * index / design.gear + reference;
            FacetPlane fp;
            fp.plane.n = glm::normalize(
                glm::dvec3(std::sin(a) * std::cos(phi), up, std::sin(a) * std::sin(phi)));
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
        const glm::dmat3 m = mirror_about_azimuth(reference);
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
