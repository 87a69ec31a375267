// What the command line overrides of the config (app/kiosk_run.hpp) and the render choice the
// config makes (stage/picture_choice.hpp), against values set by hand.
#include <gtest/gtest.h>

#include "app/kiosk_run.hpp"
#include "stage/picture_choice.hpp"

namespace gem::kiosk {
namespace {

TEST(RunOverrides, TheCommandLineOutranksTheFileAndLeavesTheRest) {
    KioskConfig config;
    config.display.backend = "drm";
    config.display.headless_width = 640;
    config.snapshot.every_n_frames = 0;
    const KioskConfig before = config;
    KioskRun run;
    run.backend = "headless";
    run.state_dir = "/tmp/state";
    apply_run_overrides(run, config);
    EXPECT_EQ(config.display.backend, "headless");
    // A state folder given moves the inbox into it.
    EXPECT_EQ(config.catalogue.state_dir, std::filesystem::path("/tmp/state"));
    EXPECT_EQ(config.catalogue.inbox_dir, std::filesystem::path("/tmp/state/inbox"));
    EXPECT_EQ(config.display.headless_width, before.display.headless_width);
    EXPECT_EQ(config.snapshot.every_n_frames, 0);
    EXPECT_EQ(config.catalogue.default_dir, before.catalogue.default_dir);
}

TEST(RenderChoiceFromConfig, AutoDrawsWithTheTableUntilChosen) {
    KioskConfig config;
    config.render.method = kAutoMethod;
    config.render.depth = 11;
    config.render.view_cache_mb = 3;
    config.picture.stone_share = 0.3;
    RenderChoice render = render_choice(config);
    EXPECT_EQ(render.method, "table");
    EXPECT_EQ(render.depth, 11);
    EXPECT_EQ(render.cache_bytes, std::size_t{3} << 20);
    EXPECT_EQ(render.stone_share, 0.3);
    config.render.method = "trace";
    EXPECT_EQ(render_choice(config).method, "trace");
}

}  // namespace
}  // namespace gem::kiosk
