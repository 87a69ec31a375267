// catalogue.toml: what a good manifest yields, and that every fault names the file, the line
// (counted by hand in the texts below) and the key.

#include <gtest/gtest.h>

#include "catalogue/manifest.hpp"
#include "catalogue_test_support.hpp"

namespace gem::kiosk {
namespace {

using namespace catalogue_test;

Result<Catalogue> parse(const std::string& name, const std::string& text) {
    const auto dir = fresh_dir("manifest-" + name);
    write_text(dir / "catalogue.toml", text);
    return read_manifest(dir);
}

void expect_error(const std::string& name, const std::string& text, const std::string& expected) {
    auto result = parse(name, text);
    ASSERT_FALSE(result.ok()) << name << " was accepted";
    EXPECT_EQ(result.error(), expected);
}

TEST(CatalogueManifest, ReadsEveryKey) {
    const auto dir = fresh_dir("manifest-full");
    write_text(dir / "catalogue.toml", R"(# a comment
[catalogue]
name = "spring"

[[stone]]
name = "Blue oval"
database = "stones/./oval.gemdb"
ring = "rings/solitaire.obj"
metal = "white_gold"
colour = [0.1, 0.2, 0.7]
absorption_per_mm = [0.5, 0.25, 0]
background = "velvet"
lighting = "window"

[[stone]]
name = "Loose diamond"
database = "diamond.gemdb"
ring = "none"

[[stone]]
name = "Halo"
piece = "pieces/halo.toml"
)");
    auto result = read_manifest(dir);
    ASSERT_TRUE(result.ok()) << result.error();
    const Catalogue& c = result.value();
    EXPECT_EQ(c.name, "spring");
    ASSERT_EQ(c.stones.size(), 3u);
    const CatalogueStone& a = c.stones[0];
    EXPECT_EQ(a.name, "Blue oval");
    EXPECT_EQ(a.database, dir / "stones" / "oval.gemdb");
    EXPECT_EQ(a.ring, RingKind::obj);
    EXPECT_EQ(a.ring_obj, dir / "rings" / "solitaire.obj");
    EXPECT_EQ(a.metal, Metal::white_gold);
    ASSERT_TRUE(a.colour.has_value());
    EXPECT_EQ(*a.colour, glm::dvec3(0.1, 0.2, 0.7));
    ASSERT_TRUE(a.absorption_per_mm.has_value());
    EXPECT_EQ(*a.absorption_per_mm, glm::dvec3(0.5, 0.25, 0.0));
    EXPECT_EQ(a.background, "velvet");
    EXPECT_EQ(a.lighting, "window");
    const CatalogueStone& b = c.stones[1];
    EXPECT_EQ(b.database, dir / "diamond.gemdb");
    EXPECT_EQ(b.ring, RingKind::none);
    // Defaults: yellow gold, no overrides, the kiosk's own presets.
    EXPECT_EQ(b.metal, Metal::yellow_gold);
    EXPECT_FALSE(b.colour.has_value());
    EXPECT_FALSE(b.absorption_per_mm.has_value());
    EXPECT_TRUE(b.background.empty());
    EXPECT_EQ(b.opened, nullptr) << "reading the manifest opens nothing";
    const CatalogueStone& halo = c.stones[2];
    EXPECT_EQ(halo.piece, dir / "pieces" / "halo.toml");
    EXPECT_TRUE(halo.database.empty());
    EXPECT_EQ(halo.placed, nullptr) << "reading the manifest reads no piece";
}

TEST(CatalogueManifest, RingDefaultsToParametric) {
    auto result = parse("ring-default", one_stone_manifest("x"));
    ASSERT_TRUE(result.ok()) << result.error();
    EXPECT_EQ(result.value().stones[0].ring, RingKind::parametric);
}

TEST(CatalogueManifest, ErrorsNameFileLineAndKey) {
    const std::string head = "[catalogue]\nname = \"x\"\n[[stone]]\nname = \"a\"\n";  // lines 1-4
    expect_error("unknown-key", head + "database = \"a.gemdb\"\ncolor = [1, 1, 1]\n",
                 "catalogue.toml:6: stone.color: unknown key");
    expect_error("rose-gold", head + "database = \"a.gemdb\"\nmetal = \"rose_gold\"\n",
                 "catalogue.toml:6: stone.metal: unknown metal 'rose_gold' (this build has "
                 "yellow_gold, white_gold, platinum, silver)");
    expect_error("bad-ring", head + "database = \"a.gemdb\"\nring = \"gold band\"\n",
                 "catalogue.toml:6: stone.ring: 'gold band' is not parametric, none or a .obj "
                 "file");
    expect_error("no-database", head + "metal = \"silver\"\n",
                 "catalogue.toml:3: stone.database: missing (or a design or a piece)");
    expect_error("both", head + "database = \"a.gemdb\"\ndesign = \"a.toml\"\n",
                 "catalogue.toml:3: stone: give one of database, design and piece, not several");
    expect_error("piece-and-design", head + "piece = \"p.toml\"\ndesign = \"a.toml\"\n",
                 "catalogue.toml:3: stone: give one of database, design and piece, not several");
    // A piece names its metal, setting and stones' materials in its own file.
    expect_error("piece-metal", head + "piece = \"p.toml\"\nmetal = \"silver\"\n",
                 "catalogue.toml:6: stone.metal: a piece gives its setting, metal and materials "
                 "in its own file");
    expect_error("piece-ring", head + "ring = \"none\"\npiece = \"p.toml\"\n",
                 "catalogue.toml:5: stone.ring: a piece gives its setting, metal and materials "
                 "in its own file");
    expect_error("piece-escapes", head + "piece = \"../p.toml\"\n",
                 "catalogue.toml:5: stone.piece: '../p.toml' must not leave the catalogue "
                 "directory");
    expect_error("design-escapes", head + "design = \"../a.toml\"\n",
                 "catalogue.toml:5: stone.design: '../a.toml' must not leave the catalogue "
                 "directory");
    expect_error("escapes", head + "database = \"../other/a.gemdb\"\n",
                 "catalogue.toml:5: stone.database: '../other/a.gemdb' must not leave the "
                 "catalogue directory");
    expect_error("absolute", head + "database = \"/etc/a.gemdb\"\n",
                 "catalogue.toml:5: stone.database: '/etc/a.gemdb' must be relative to the "
                 "catalogue directory");
    expect_error("colour-range", head + "database = \"a.gemdb\"\ncolour = [0.5, 1.5, 0]\n",
                 "catalogue.toml:6: stone.colour: components must be 0..1");
    expect_error("colour-shape", head + "database = \"a.gemdb\"\ncolour = [0.5, 1]\n",
                 "catalogue.toml:6: stone.colour: expected [r, g, b]");
    expect_error("absorption-negative",
                 head + "database = \"a.gemdb\"\nabsorption_per_mm = [0, -1, 0]\n",
                 "catalogue.toml:6: stone.absorption_per_mm: components must be >= 0");
    expect_error("name-type", "[catalogue]\nname = 3\n",
                 "catalogue.toml:2: catalogue.name: "
                 "expected a string");
    expect_error("catalogue-key", "[catalogue]\nname = \"x\"\ntitle = \"y\"\n",
                 "catalogue.toml:3: catalogue.title: unknown key");
    expect_error("top-key", "[catalogue]\nname = \"x\"\n[shop]\n",
                 "catalogue.toml:3: shop: "
                 "unknown key");
    expect_error("no-stones", "[catalogue]\nname = \"x\"\n",
                 "catalogue.toml:1: stone: no [[stone]] entries");
    expect_error("no-name", "[[stone]]\nname = \"a\"\ndatabase = \"a.gemdb\"\n",
                 "catalogue.toml:1: catalogue.name: missing");
    expect_error("duplicate",
                 head + "database = \"a.gemdb\"\n[[stone]]\nname = \"a\"\ndatabase = \"b.gemdb\"\n",
                 "catalogue.toml:7: stone.name: 'a' appears twice");
}

TEST(CatalogueManifest, ShippedDefaultManifestParses) {
    auto result = read_manifest(std::filesystem::path(GEM_SOURCE_DIR) / "config" / "catalogue");
    ASSERT_TRUE(result.ok()) << result.error();
    EXPECT_FALSE(result.value().stones.empty());
}

TEST(CatalogueManifest, SyntaxErrorNamesItsLine) {
    auto result = parse("syntax", "[catalogue]\nname = \"x\"\n[[stone]]\nname = \"a\n");
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.error().rfind("catalogue.toml:4: syntax: ", 0), 0u) << result.error();
}

TEST(CatalogueManifest, MissingManifestIsNamed) {
    const auto dir = fresh_dir("manifest-missing");
    auto result = read_manifest(dir);
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.error().rfind("catalogue.toml: ", 0), 0u) << result.error();
}

}  // namespace
}  // namespace gem::kiosk
