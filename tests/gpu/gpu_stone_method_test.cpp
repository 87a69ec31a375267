// The stone methods' registry (gpu/stone_method.hpp): every name finds its entry, an unknown one
// is refused by the frame renderer with the names this build has, and a method that draws one
// loose stone from tables refuses a piece by name.

#include <gtest/gtest.h>

#include <set>
#include <string>

#include "../unit/trace_cut_stones.hpp"
#include "gpu/frame_renderer.hpp"
#include "gpu/program_catalog.hpp"
#include "gpu/stone_method.hpp"
#include "gpu_test_support.hpp"

namespace gem::gpu {
namespace {

TEST(StoneMethodRegistry, EveryNameFindsItsOwnEntryOnce) {
    std::set<std::string> names;
    for (const MethodEntry* entry : stone_methods()) {
        EXPECT_TRUE(names.insert(std::string(entry->name)).second) << entry->name;
        EXPECT_EQ(find_stone_method(entry->name), entry);
        EXPECT_NE(entry->make, nullptr) << entry->name;
    }
    EXPECT_EQ(names, (std::set<std::string>{"trace", "table", "phong"}));
    EXPECT_EQ(find_stone_method("raymarch"), nullptr);
    EXPECT_EQ(stone_method_names(), "trace, table, phong");
}

// Each entry brings its programs and its rungs of the probe's ladder, and the catalogue and the
// ladder list them from the registry.
TEST(StoneMethodRegistry, AnEntryBringsItsProgramsAndItsRungs) {
    std::set<std::string> catalogued;
    for (const ProgramSpec& spec : all_program_specs()) {
        EXPECT_TRUE(catalogued.insert(spec.name).second) << spec.name << " twice";
    }
    const RungContext context{2, true};
    std::vector<MethodRung> expected;
    for (const MethodEntry* entry : stone_methods()) {
        ASSERT_NE(entry->programs, nullptr) << entry->name;
        ASSERT_NE(entry->rungs, nullptr) << entry->name;
        const std::vector<ProgramSpec> own = entry->programs();
        EXPECT_FALSE(own.empty()) << entry->name;
        for (const ProgramSpec& spec : own) EXPECT_TRUE(catalogued.count(spec.name)) << spec.name;
        for (const MethodRung& rung : entry->rungs(context)) {
            EXPECT_EQ(rung.method, entry->name) << rung.name;
            expected.push_back(rung);
        }
    }
    const std::vector<MethodRung> ladder = method_rungs(context);
    ASSERT_EQ(ladder.size(), expected.size());
    for (std::size_t i = 0; i < ladder.size(); ++i) EXPECT_EQ(ladder[i].name, expected[i].name);
    // What the scene draws a design or a piece with where the configured method cannot, and a
    // stone with tables before the probe chooses: read from the flags, as set by hand here.
    EXPECT_EQ(fallback_stone_method().name, "trace");
    EXPECT_EQ(tables_method().name, "table");
    EXPECT_TRUE(find_stone_method("phong")->opacity_from_alpha);
    EXPECT_FALSE(find_stone_method("phong")->refracts);
}

TEST(StoneMethodRegistry, TheFrameRendererRefusesAnUnknownMethodAndATablePiece) {
    ASSERT_TRUE(gpu_test::context().ok());
    const Environment environment = Environment::studio();
    FrameSetup setup;
    setup.method = "raymarch";
    setup.stone = test::round_diamond(4.0);
    setup.environment = &environment;
    setup.cube_face = 16;
    auto unknown = FrameRenderer::make(setup);
    ASSERT_FALSE(unknown.ok());
    EXPECT_EQ(unknown.error(),
              "frame renderer: no stone method 'raymarch' (this build has trace, table, phong)");

    Piece piece;
    piece.kinds.push_back(setup.stone);
    piece.stones.push_back({0, {}, "centre"});
    setup.method = "table";
    setup.piece = &piece;
    auto no_tables = FrameRenderer::make(setup);
    ASSERT_FALSE(no_tables.ok());
    EXPECT_EQ(no_tables.error(), "frame renderer: the table method needs a database");
    setup.method = "trace";
    auto traced = FrameRenderer::make(setup);
    ASSERT_TRUE(traced.ok()) << traced.error();
    EXPECT_TRUE(traced.value().model(0).has_value()) << "the trace has a model per kind";
    setup.method = "phong";
    auto flat = FrameRenderer::make(setup);
    ASSERT_TRUE(flat.ok()) << flat.error();
    EXPECT_FALSE(flat.value().model(0).has_value());
}

}  // namespace
}  // namespace gem::gpu
