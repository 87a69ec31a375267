// A design's tables, built in the background by the real gemtables (tiny settings, so a build
// takes a fraction of a second): when the trace's frames miss the budget they are built,
// checked and switched to; kept when their frames are faster, dropped and remembered when
// not; found again by a second DesignTables on the same folder (a restart); a failing builder
// gets one error line and the trace stays. Frame times are given by the test, so every verdict
// follows from numbers worked by hand (nearest-rank p90 of six frames = the slowest).
#include <sys/stat.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <thread>

#include "builds/design_tables.hpp"
#include "gemdb/sections.hpp"
#include "piece/piece_file.hpp"
#include "scene/stone_file.hpp"

namespace gem::kiosk {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

constexpr double kBudgetMs = 10.0;

class DesignTablesTest : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = fs::path(GEM_ARTIFACT_DIR) /
               ::testing::UnitTest::GetInstance()->current_test_info()->name();
        fs::remove_all(dir_);
        fs::create_directories(dir_);
        // A 2 mm emerald cut in emerald: its material does not disperse, so no fire is stored.
        stone_.name = "emerald";
        stone_.design = dir_ / "emerald.toml";
        std::ofstream(stone_.design)
            << "[stone]\ncut = \"emerald\"\nwidth_mm = 2.0\n\n[material]\nname = \"emerald\"\n";
        auto designed = load_stone_file(stone_.design);
        ASSERT_TRUE(designed.ok()) << designed.error();
        stone_.designed = std::make_shared<const Stone>(std::move(designed).value());
        config_.builder = GEMTABLES_PATH;
        config_.level_px = 16;
        config_.spacing_deg = 30.0;
        config_.depth = 2;
        config_.jobs = 1;
    }

    // Two frames that are not timed (shader compiles), then `n` of `ms` each.
    void frames(DesignTables& tables, bool from_tables, int n, double ms) {
        const DesignTables::KindTables drawn =
            from_tables ? tables.tables_for(stone_) : DesignTables::KindTables{};
        for (int i = 0; i < 2 + n; ++i) tables.frame_drawn(stone_, drawn, i, ms, kBudgetMs);
    }

    // The design's tables in use, or null.
    std::shared_ptr<const Database> tables_of(const DesignTables& tables) const {
        const DesignTables::KindTables kinds = tables.tables_for(stone_);
        return kinds.empty() ? nullptr : kinds.front();
    }

    // Calls dispatch() as the main loop does until it reports a switch; false after 60 s.
    bool wait_for_switch(DesignTables& tables) {
        const auto give_up = Clock::now() + std::chrono::seconds(60);
        while (Clock::now() < give_up) {
            if (tables.dispatch(&stone_)) return true;
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
        }
        return false;
    }

    fs::path tables_dir() const { return dir_ / "tables"; }

    fs::path dir_;
    CatalogueStone stone_;
    DesignsConfig config_;
};

TEST_F(DesignTablesTest, OverBudgetTablesAreBuiltAtIdlePriorityUsedAndFoundAfterARestart) {
    const fs::path file = [&] {
        DesignTables tables(config_, tables_dir());
        EXPECT_FALSE(tables.dispatch(&stone_));
        EXPECT_EQ(tables_of(tables), nullptr);
        // Six trace frames of 25 ms against a 10 ms budget: p90 25 ms, over.
        testing::internal::CaptureStderr();
        frames(tables, false, 6, 25.0);
        EXPECT_TRUE(wait_for_switch(tables));
        const std::string log = testing::internal::GetCapturedStderr();
        EXPECT_NE(log.find("p90 25.0 ms, over the 10.0 ms budget"), std::string::npos) << log;
        EXPECT_NE(log.find("running at idle CPU priority (SCHED_IDLE), nice 19"), std::string::npos)
            << log;
        auto database = tables_of(tables);
        EXPECT_NE(database, nullptr);
        if (!database) return fs::path();
        EXPECT_EQ(database->path(), tables.tables_path(stone_));
        EXPECT_EQ(database->stone().facets.size(), stone_.designed->facets.size());
        EXPECT_EQ(database->params().levels, (std::vector<std::uint32_t>{8, 16}));
        // Tables at 15 ms against the trace's 25 ms: they pay and stay.
        testing::internal::CaptureStderr();
        frames(tables, true, 6, 15.0);
        EXPECT_FALSE(tables.dispatch(&stone_));
        const std::string verdict = testing::internal::GetCapturedStderr();
        EXPECT_NE(verdict.find("its tables pay: p90 15.0 ms against the trace's 25.0 ms"),
                  std::string::npos)
            << verdict;
        EXPECT_NE(tables_of(tables), nullptr);
        return database->path();
    }();
    ASSERT_TRUE(fs::exists(file));
    // The database and its verdict are left in the folder, and no temporary.
    std::vector<std::string> left;
    for (const auto& e : fs::directory_iterator(tables_dir())) {
        left.push_back(e.path().filename().string());
    }
    std::sort(left.begin(), left.end());
    const std::string stem = file.stem().string();
    EXPECT_EQ(left, (std::vector<std::string>{stem + ".gemdb", stem + ".pays"}));

    // A restart: the tables are checked and used without timing or building anything.
    const auto modified = fs::last_write_time(file);
    DesignTables again(config_, tables_dir());
    testing::internal::CaptureStderr();
    EXPECT_TRUE(wait_for_switch(again));
    const std::string log = testing::internal::GetCapturedStderr();
    EXPECT_NE(tables_of(again), nullptr);
    EXPECT_EQ(log.find("building"), std::string::npos) << log;
    EXPECT_EQ(fs::last_write_time(file), modified);
}

// A kiosk stopped after its tables were built but before they were timed: the next run times
// the trace first, then takes the tables it finds (no second build) and times them.
TEST_F(DesignTablesTest, TablesWithoutAVerdictAreTimedAgainAfterARestart) {
    fs::path file;
    {
        DesignTables tables(config_, tables_dir());
        frames(tables, false, 6, 25.0);
        ASSERT_TRUE(wait_for_switch(tables));
        file = tables.tables_path(stone_);
    }
    ASSERT_TRUE(fs::exists(file));
    DesignTables again(config_, tables_dir());
    testing::internal::CaptureStderr();
    EXPECT_FALSE(again.dispatch(&stone_));
    EXPECT_FALSE(again.busy());  // nothing checked or built before the trace is timed
    EXPECT_EQ(tables_of(again), nullptr);
    frames(again, false, 6, 25.0);
    EXPECT_TRUE(wait_for_switch(again));
    EXPECT_NE(tables_of(again), nullptr);
    frames(again, true, 6, 15.0);
    EXPECT_FALSE(again.dispatch(&stone_));
    const std::string log = testing::internal::GetCapturedStderr();
    EXPECT_NE(log.find("over the 10.0 ms budget: checking the tables built before"),
              std::string::npos)
        << log;
    EXPECT_EQ(log.find("building its tables"), std::string::npos) << log;
    EXPECT_NE(log.find("its tables pay: p90 15.0 ms against the trace's 25.0 ms"),
              std::string::npos)
        << log;
    EXPECT_TRUE(fs::exists(fs::path(file).replace_extension(".pays")));
}

TEST_F(DesignTablesTest, SlowerTablesAreDroppedAndNotBuiltAgain) {
    {
        DesignTables tables(config_, tables_dir());
        frames(tables, false, 6, 25.0);
        ASSERT_TRUE(wait_for_switch(tables));
        ASSERT_NE(tables_of(tables), nullptr);
        // Tables at 40 ms against the trace's 25 ms: back to the trace, at the next dispatch.
        frames(tables, true, 6, 40.0);
        EXPECT_TRUE(tables.dispatch(&stone_));
        EXPECT_EQ(tables_of(tables), nullptr);
    }
    EXPECT_FALSE(fs::exists(DesignTables(config_, tables_dir()).tables_path(stone_)));
    // Only the verdict is left.
    std::vector<fs::path> left;
    for (const auto& e : fs::directory_iterator(tables_dir())) left.push_back(e.path());
    ASSERT_EQ(left.size(), 1u);
    EXPECT_EQ(left[0].extension(), ".trace");

    // A restart times the trace over budget again, but builds nothing.
    DesignTables again(config_, tables_dir());
    testing::internal::CaptureStderr();
    EXPECT_FALSE(again.dispatch(&stone_));
    frames(again, false, 6, 25.0);
    EXPECT_FALSE(again.dispatch(&stone_));
    const std::string log = testing::internal::GetCapturedStderr();
    EXPECT_FALSE(again.busy());
    EXPECT_EQ(tables_of(again), nullptr);
    EXPECT_NE(log.find("did not pay on this machine"), std::string::npos) << log;

    // Staff who ask for tables whatever they cost get them all the same.
    config_.tables = DesignTablesMode::always;
    DesignTables asked(config_, tables_dir());
    EXPECT_TRUE(wait_for_switch(asked));
    EXPECT_NE(tables_of(asked), nullptr);
}

TEST_F(DesignTablesTest, ATraceWithinTheBudgetBuildsNothing) {
    DesignTables tables(config_, tables_dir());
    EXPECT_FALSE(tables.dispatch(&stone_));
    // p90 of six frames of 10 ms is the budget itself: held.
    frames(tables, false, 6, 10.0);
    EXPECT_FALSE(tables.dispatch(&stone_));
    EXPECT_FALSE(tables.busy());
    EXPECT_EQ(tables.fd(), -1);
    EXPECT_FALSE(fs::exists(tables_dir()));
}

TEST_F(DesignTablesTest, NeverAndAlways) {
    config_.tables = DesignTablesMode::never;
    {
        DesignTables tables(config_, tables_dir());
        frames(tables, false, 6, 1000.0);
        EXPECT_FALSE(tables.dispatch(&stone_));
        EXPECT_FALSE(tables.busy());
    }
    // Always: built on first sight, no frame timed, and kept whatever its frames cost.
    config_.tables = DesignTablesMode::always;
    DesignTables tables(config_, tables_dir());
    EXPECT_TRUE(wait_for_switch(tables));
    frames(tables, true, 6, 1000.0);
    EXPECT_FALSE(tables.dispatch(&stone_));
    EXPECT_NE(tables_of(tables), nullptr);
}

TEST_F(DesignTablesTest, AFailingBuilderIsOneErrorLineAndTheTraceStays) {
    // A builder that fails as gemtables does on a full disk.
    const fs::path builder = dir_ / "failing-builder";
    std::ofstream(builder) << "#!/bin/sh\necho 'gemtables: cannot write x: No space left on "
                              "device' >&2\nexit 1\n";
    fs::permissions(builder, fs::perms::owner_all);
    config_.builder = builder;
    DesignTables tables(config_, tables_dir());
    testing::internal::CaptureStderr();
    frames(tables, false, 6, 25.0);
    const auto give_up = Clock::now() + std::chrono::seconds(30);
    do {
        EXPECT_FALSE(tables.dispatch(&stone_));
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    } while (tables.busy() && Clock::now() < give_up);
    frames(tables, false, 6, 25.0);  // no second build
    EXPECT_FALSE(tables.dispatch(&stone_));
    const std::string log = testing::internal::GetCapturedStderr();
    EXPECT_FALSE(tables.busy());
    EXPECT_EQ(tables_of(tables), nullptr);
    const auto error = log.find("<3>");
    ASSERT_NE(error, std::string::npos) << log;
    EXPECT_EQ(log.find("<3>", error + 1), std::string::npos) << log;  // one error line
    const std::string line = log.substr(error, log.find('\n', error) - error);
    EXPECT_NE(line.find("design 'emerald': its tables could not be built (the builder exited "
                        "with status 1: gemtables: cannot write x: No space left on device); "
                        "it stays drawn by the trace"),
              std::string::npos)
        << line;

    // A builder that is not there: the same, with the reason.
    config_.builder = dir_ / "no-such-builder";
    DesignTables missing(config_, dir_ / "other-tables");
    testing::internal::CaptureStderr();
    frames(missing, false, 6, 25.0);
    EXPECT_FALSE(missing.dispatch(&stone_));
    const std::string why = testing::internal::GetCapturedStderr();
    EXPECT_NE(why.find("its tables cannot be built: cannot start"), std::string::npos) << why;
    EXPECT_FALSE(missing.busy());
}

TEST_F(DesignTablesTest, DamagedTablesAreRemovedAndBuiltAgain) {
    config_.tables = DesignTablesMode::always;
    fs::path file;
    {
        DesignTables tables(config_, tables_dir());
        ASSERT_TRUE(wait_for_switch(tables));
        file = tables.tables_path(stone_);
    }
    // A byte near the end lies in the last view's payload: the file opens, its checksum fails.
    {
        std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
        f.seekg(-3, std::ios::end);
        const char c = static_cast<char>(f.get() ^ 0x10);
        f.seekp(-3, std::ios::end);
        f.put(c);
    }
    DesignTables again(config_, tables_dir());
    testing::internal::CaptureStderr();
    EXPECT_TRUE(wait_for_switch(again));
    const std::string log = testing::internal::GetCapturedStderr();
    EXPECT_NE(log.find("checksum mismatch"), std::string::npos) << log;
    EXPECT_NE(log.find("building its tables"), std::string::npos) << log;
    EXPECT_NE(tables_of(again), nullptr);
}

// A piece's non-convex stones (the trilogy's heart side stones; its oval centre is convex) get
// tables of their own, sized as the piece sizes them and storing every direction, so the frame
// renderer draws them placed (gpu/piece_tables.hpp); the piece's frames judge them.
TEST_F(DesignTablesTest, APiecesNonConvexStonesGetTablesOfTheStoneThePiecePlaces) {
    const fs::path stones = fs::path(GEM_SOURCE_DIR) / "config" / "stones";
    CatalogueStone trio;
    trio.name = "Heart trio";
    trio.piece = dir_ / "trio.toml";
    std::ofstream(trio.piece) << "[piece]\nname = \"Heart trio\"\nsetting = \"three-stone\"\n\n"
                                 "[centre]\nstone = \""
                              << (stones / "oval-sapphire.toml").string()
                              << "\"\n\n[small]\nstone = \""
                              << (stones / "heart-ruby.toml").string() << "\"\nwidth_mm = 4.0\n";
    auto piece = load_piece(trio.piece);
    ASSERT_TRUE(piece) << piece.error();
    trio.placed = std::make_shared<const Piece>(std::move(piece).value());
    const Piece& placed = *trio.placed;
    ASSERT_EQ(placed.kinds.size(), 2u);
    ASSERT_TRUE(placed.kinds[0].convex);
    ASSERT_FALSE(placed.kinds[1].convex);

    const std::vector<TabledStone> tabled = tabled_stones(trio);
    ASSERT_EQ(tabled.size(), 1u);
    EXPECT_EQ(tabled[0].kind, 1u);
    EXPECT_EQ(tabled[0].width_mm, 4.0);
    EXPECT_TRUE(tabled[0].whole_sphere);
    EXPECT_EQ(tabled[0].who, "piece 'Heart trio': its 4.0 mm stone 'heart'");

    DesignTables tables(config_, tables_dir());
    EXPECT_FALSE(tables.dispatch(&trio));
    testing::internal::CaptureStderr();
    for (int i = 0; i < 8; ++i) tables.frame_drawn(trio, {}, i, 25.0, kBudgetMs);
    bool switched = false;
    for (const auto give_up = Clock::now() + std::chrono::seconds(60);
         !switched && Clock::now() < give_up;) {
        switched = tables.dispatch(&trio);
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    const std::string log = testing::internal::GetCapturedStderr();
    ASSERT_TRUE(switched) << log;
    EXPECT_NE(log.find("piece 'Heart trio': its 4.0 mm stone 'heart': the trace draws it in p90 "
                       "25.0 ms"),
              std::string::npos)
        << log;
    const DesignTables::KindTables kinds = tables.tables_for(trio);
    ASSERT_EQ(kinds.size(), 2u);
    EXPECT_EQ(kinds[0], nullptr);  // the convex centre stays traced
    ASSERT_NE(kinds[1], nullptr);
    // The very stone the piece places, every direction stored.
    EXPECT_TRUE(same_stored_stone(kinds[1]->stone(), placed.kinds[1]));
    EXPECT_EQ(kinds[1]->params().grid.min_elevation_rad, -std::numbers::pi / 2.0);

    // The piece's frames drawn with them, faster: they pay and stay.
    testing::internal::CaptureStderr();
    for (int i = 0; i < 8; ++i) tables.frame_drawn(trio, kinds, i, 15.0, kBudgetMs);
    EXPECT_FALSE(tables.dispatch(&trio));
    const std::string verdict = testing::internal::GetCapturedStderr();
    EXPECT_NE(verdict.find("its tables pay: p90 15.0 ms against the trace's 25.0 ms"),
              std::string::npos)
        << verdict;
    EXPECT_EQ(tables.tables_for(trio).size(), 2u);
}

}  // namespace
}  // namespace gem::kiosk
