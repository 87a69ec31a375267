#include "optics/material.hpp"

#include <algorithm>
#include <cassert>
#include <cctype>
#include <cmath>
#include <initializer_list>
#include <utility>

#include "optics/spectrum.hpp"

namespace gem {

namespace {

double squared_um(double wavelength_nm) {
    const double um = wavelength_nm * 1e-3;
    return um * um;
}

// Sellmeier terms come in (B_i, C_i) pairs; two-term fits (diamond) are padded with zeros
// to the three pairs the header describes, so any even count of coefficients is accepted.
double sellmeier_index(const std::vector<double>& coef, double wavelength_nm) {
    assert(!coef.empty() && coef.size() % 2 == 0);
    const double l2 = squared_um(wavelength_nm);
    double n2 = 1.0;
    for (std::size_t i = 0; i + 1 < coef.size(); i += 2) {
        assert(l2 != coef[i + 1]);  // a resonance inside the visible range is a data bug
        n2 += coef[i] * l2 / (l2 - coef[i + 1]);
    }
    assert(n2 > 0.0);
    return std::sqrt(n2);
}

}  // namespace

double Dispersion::index(double wavelength_nm) const {
    assert(wavelength_nm > 0.0);
    switch (kind) {
        case Kind::constant:
            assert(coef.size() >= 1);
            return coef[0];
        case Kind::cauchy:
            assert(coef.size() >= 2);
            return coef[0] + coef[1] / squared_um(wavelength_nm);
        case Kind::sellmeier:
            return sellmeier_index(coef, wavelength_nm);
    }
    assert(false && "unknown dispersion kind");
    return coef.empty() ? 1.0 : coef[0];
}

Dispersion Dispersion::constant_index(double n) {
    Dispersion d;
    d.kind = Kind::constant;
    d.coef = {n};
    return d;
}

// Two-term Cauchy n = A + B/λ² through n(D) and the gemmological dispersion n(G) − n(B).
// Since n(G) − n(B) = B (1/λG² − 1/λB²), B follows from the dispersion alone and A from n(D):
// the fit reproduces n(D) and the whole B–G interval (686.7 → 430.8 nm) exactly by
// construction. The single values n(G) and n(B) are each off by the same amount, because a
// real index curves more steeply toward the UV than 1/λ². Checked against diamond's
// Sellmeier curve (Peter 1923): n(G) and n(B) are both 0.0003 low, the error is −0.0005 at
// 730 nm and −0.0018 at 380 nm (4 % of diamond's dispersion); for corundum (Malitson &
// Dodge 1972) and N-BK7 (Schott) the error stays below 0.0004 over 380–730 nm. Good enough
// for rendering fire; use a Sellmeier fit where one is published.
Dispersion Dispersion::cauchy_from_nd(double nd, double dispersion_bg) {
    const double span = 1.0 / squared_um(kFraunhoferG) - 1.0 / squared_um(kFraunhoferB);
    const double b = dispersion_bg / span;
    Dispersion d;
    d.kind = Kind::cauchy;
    d.coef = {nd - b / squared_um(kFraunhoferD), b};
    return d;
}

namespace {

Dispersion sellmeier(std::initializer_list<double> coef) {
    Dispersion d;
    d.kind = Dispersion::Kind::sellmeier;
    d.coef.assign(coef);
    while (d.coef.size() < 6) d.coef.push_back(0.0);
    return d;
}

// Coloured stones: handbooks give absorption spectra (band positions), not RGB. Each stone's
// colour is given here as the linear-RGB share of white light that survives a reference path
// of kReferencePathMm inside it, chosen by hand to match the stone's typical hue and where
// its published absorption bands sit. These are approximations for rendering, not
// measurements. From that one figure: absorption σ = −ln(T)/L per channel (Beer–Lambert),
// and the body colour I_o = T scaled so its brightest channel is 1 (a hue, not a darkness,
// since the thesis multiplies I_o by the light).
constexpr double kReferencePathMm = 2.0;

Material make_material(const char* name, Dispersion dispersion, glm::dvec3 transmittance) {
    assert(glm::all(glm::greaterThan(transmittance, glm::dvec3(0.0))));
    assert(glm::all(glm::lessThanEqual(transmittance, glm::dvec3(1.0))));
    Material m;
    m.name = name;
    m.dispersion = std::move(dispersion);
    m.absorption_per_mm = glm::log(1.0 / transmittance) / kReferencePathMm;
    const double brightest = std::max({transmittance.x, transmittance.y, transmittance.z});
    m.body_colour = transmittance / brightest;
    return m;
}

constexpr glm::dvec3 kColourless{1.0};

std::vector<Material> make_catalogue() {
    std::vector<Material> list;

    // Diamond. Sellmeier fit of Peter (1923, Z. Phys. 15, 358), as quoted in Weber, Handbook
    // of Optical Materials (CRC 2003) §1.3.4: n² = 1 + 0.3306 λ²/(λ² − 0.175²)
    // + 4.3356 λ²/(λ² − 0.106²). It gives n_D = 2.4173 and n(G) − n(B) = 0.0444, matching
    // the GIA Gem Reference Guide (1995): RI 2.417, dispersion 0.044. Colourless (type IIa);
    // most diamonds are faintly yellow, which a catalogue entry can set.
    list.push_back(make_material(
        "diamond", sellmeier({0.3306, 0.175 * 0.175, 4.3356, 0.106 * 0.106}), kColourless));

    // Corundum (sapphire, ruby). Ordinary-ray Sellmeier of Malitson & Dodge (1972), "Refractive
    // index and birefringence of synthetic sapphire", JOSA 62, 1405: B = 1.4313493,
    // 0.65054713, 5.3414021; λ_i = 0.0726631, 0.1193242, 18.028251 µm. It gives n_D = 1.7681
    // and B–G 0.0181 (GIA: RI 1.762–1.770, birefringence 0.008, dispersion 0.018). The
    // ordinary ray is used since the birefringence (0.008) is too small to see in a render.
    // Cr³⁺ in ruby changes the index by less than the natural range, so both share the fit.
    const Dispersion corundum =
        sellmeier({1.4313493, 0.0726631 * 0.0726631, 0.65054713, 0.1193242 * 0.1193242, 5.3414021,
                   18.028251 * 18.028251});

    // Blue sapphire: the Fe²⁺–Ti⁴⁺ charge-transfer band is broad and centred near 565–580 nm,
    // Fe³⁺ adds weak lines at 450 nm (Fritsch & Rossman, "An update on color in gems, part 2",
    // Gems & Gemology 24(1), 1988); blue passes, red and most green are absorbed.
    list.push_back(make_material("sapphire", corundum, {0.10, 0.22, 0.70}));

    // Ruby: Cr³⁺ bands near 410 nm and 555 nm (Fritsch & Rossman, part 1, G&G 23(3), 1987)
    // leave the red above 610 nm and a weaker blue window near 470 nm (hence a slightly
    // purplish red).
    list.push_back(make_material("ruby", corundum, {0.80, 0.06, 0.20}));

    // Emerald (beryl). GIA: RI 1.577–1.583, dispersion 0.014; the mean 1.580 of the ordinary
    // and extraordinary rays is used (birefringence 0.006 is not rendered). Cauchy fit, as no
    // Sellmeier fit of gem beryl is known to us. Colour: Cr³⁺ bands near 430 and 610 nm
    // (Fritsch & Rossman 1987) leave a green window near 510 nm.
    list.push_back(
        make_material("emerald", Dispersion::cauchy_from_nd(1.580, 0.014), {0.25, 0.70, 0.30}));

    // Garnet: almandine (the common red garnet). GIA: RI 1.790 (±0.030), dispersion 0.024.
    // Colour: the Fe²⁺ bands at 505, 527 and 576 nm (the "almandine spectrum") and a rising
    // absorption in the violet leave a deep, slightly purplish red.
    list.push_back(
        make_material("garnet", Dispersion::cauchy_from_nd(1.790, 0.024), {0.55, 0.04, 0.07}));

    // Spinel (red). GIA: RI 1.718 (+0.017/−0.008), dispersion 0.020. Colour: Cr³⁺ bands near
    // 400 and 540 nm (Fritsch & Rossman 1987) give a red a little lighter and pinker than ruby.
    list.push_back(
        make_material("spinel", Dispersion::cauchy_from_nd(1.718, 0.020), {0.85, 0.12, 0.30}));

    // Cubic zirconia (yttrium-stabilised). GIA: RI 2.15–2.18, dispersion 0.058–0.066; the
    // middle values 2.165 and 0.060 are used. Colourless.
    list.push_back(
        make_material("cubic zirconia", Dispersion::cauchy_from_nd(2.165, 0.060), kColourless));

    // Synthetic moissanite (6H SiC). Nassau, McClure, Elen & Shigley, "Synthetic moissanite: a
    // new diamond substitute", Gems & Gemology 33(4), 1997: RI 2.648 (ω) – 2.691 (ε),
    // dispersion 0.104. It is uniaxial; stones are cut with the table perpendicular to the
    // optic axis to hide the doubling, so light seen through the table is mostly the ordinary
    // ray: n = ω = 2.648. Rendered colourless (commercial stones are near-colourless).
    list.push_back(
        make_material("moissanite", Dispersion::cauchy_from_nd(2.648, 0.104), kColourless));

    // Quartz (rock crystal). GIA: RI 1.544–1.553, dispersion 0.013; ordinary ray ω = 1.544 as
    // for moissanite (birefringence 0.009 is not rendered). Colourless.
    list.push_back(make_material("quartz", Dispersion::cauchy_from_nd(1.544, 0.013), kColourless));

    // Crown glass: Schott N-BK7 datasheet Sellmeier, B = 1.03961212, 0.231792344,
    // 1.01046945; C = 0.00600069867, 0.0200179144, 103.560653 µm². n_d(587.6 nm) = 1.5168,
    // n_D = 1.5167, B–G 0.0138. Colourless.
    list.push_back(make_material(
        "crown glass",
        sellmeier({1.03961212, 0.00600069867, 0.231792344, 0.0200179144, 1.01046945, 103.560653}),
        kColourless));
    return list;
}

// Lower case without spaces, hyphens or underscores: "Cubic-Zirconia" == "cubic zirconia".
std::string lookup_key(std::string_view name) {
    std::string key;
    key.reserve(name.size());
    for (const char c : name) {
        if (c == ' ' || c == '-' || c == '_') continue;
        key.push_back(static_cast<char>(std::tolower(static_cast<unsigned char>(c))));
    }
    return key;
}

struct Alias {
    const char* key;
    const char* material;
};

constexpr Alias kAliases[] = {
    {"cz", "cubic zirconia"}, {"zirconia", "cubic zirconia"}, {"almandine", "garnet"},
    {"bk7", "crown glass"},   {"nbk7", "crown glass"},        {"glass", "crown glass"},
    {"crown", "crown glass"}, {"sic", "moissanite"},          {"rockcrystal", "quartz"},
    {"corundum", "sapphire"}, {"bluesapphire", "sapphire"},   {"redspinel", "spinel"},
};

}  // namespace

const std::vector<Material>& builtin_materials() {
    static const std::vector<Material> catalogue = make_catalogue();
    return catalogue;
}

std::optional<Material> find_material(std::string_view name) {
    std::string key = lookup_key(name);
    for (const Alias& alias : kAliases) {
        if (key == alias.key) {
            key = lookup_key(alias.material);
            break;
        }
    }
    for (const Material& m : builtin_materials()) {
        if (lookup_key(m.name) == key) return m;
    }
    return std::nullopt;
}

// Material::index() asserts on a Sellmeier resonance at the asked wavelength and on n² ≤ 0,
// and shading assumes n ≥ 1: so a stored dispersion must have no Sellmeier resonance in the
// rendered range and give a finite n ≥ 1 across it (1 nm steps; `coef` already fits `kind`).
bool Dispersion::is_physical() const {
    const Dispersion& d = *this;
    const auto l2 = [](double nm) { return nm * nm * 1e-6; };  // µm²
    if (d.kind == Dispersion::Kind::sellmeier) {
        for (std::size_t i = 0; i + 1 < d.coef.size(); i += 2) {
            const double c = d.coef[i + 1];
            if (c >= l2(kSpectrumMinNm - 1.0) && c <= l2(kSpectrumMaxNm + 1.0)) return false;
        }
    }
    for (double nm = kSpectrumMinNm; nm <= kSpectrumMaxNm; nm += 1.0) {
        double n2 = 0.0;
        switch (d.kind) {
            case Dispersion::Kind::constant:
                n2 = d.coef[0] * std::abs(d.coef[0]);
                break;
            case Dispersion::Kind::cauchy: {
                const double n = d.coef[0] + d.coef[1] / l2(nm);
                n2 = n * std::abs(n);
                break;
            }
            case Dispersion::Kind::sellmeier:
                n2 = 1.0;
                for (std::size_t i = 0; i + 1 < d.coef.size(); i += 2) {
                    n2 += d.coef[i] * l2(nm) / (l2(nm) - d.coef[i + 1]);
                }
                break;
        }
        if (!(std::isfinite(n2) && n2 >= 1.0)) return false;
    }
    return true;
}

}  // namespace gem
