// The gemtables program run as a user runs it (its path comes from the build as
// GEMTABLES_PATH): build → info → verify on a tiny stone at a tiny resolution, a damaged copy,
// bad stone files, the atomic output and the inspect pictures.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

#include "gemdb/reader.hpp"
#include "gemdb/sections.hpp"
#include "picture/image.hpp"
#include "piece/piece_file.hpp"
#include "piece/stone_shape.hpp"
#include "tables_test_support.hpp"

namespace gem {
namespace {

namespace fs = std::filesystem;

struct Outcome {
    int status = -1;
    std::string output;  // stdout and stderr together
};

Outcome run(const std::string& arguments) {
    const std::string command = std::string(GEMTABLES_PATH) + " " + arguments + " 2>&1";
    Outcome r;
    std::FILE* pipe = ::popen(command.c_str(), "r");
    if (pipe == nullptr) return r;
    char buffer[4096];
    std::size_t n = 0;
    while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) r.output.append(buffer, n);
    const int raw = ::pclose(pipe);
    r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    return r;
}

fs::path write_text(const fs::path& path, const std::string& text) {
    std::ofstream(path, std::ios::trunc) << text;
    return path;
}

// A 2 mm round brilliant in diamond: big enough to fill a few pixels, quick to trace.
fs::path tiny_stone(const fs::path& dir) {
    return write_text(
        dir / "tiny.toml",
        "[stone]\ncut = \"round\"\nwidth_mm = 2.0\n\n[material]\nname = \"diamond\"\n");
}

const char* kTinyOptions = "--levels 4,8 --spacing 40 --min-elevation 0 --jobs 2";

class GemtablesCli : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = tables_test::artifact_dir(
            std::string("gemtables_") +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
        stone_ = tiny_stone(dir_);
    }
    fs::path dir_;
    fs::path stone_;
};

TEST_F(GemtablesCli, BuildInfoVerifySucceed) {
    const fs::path db = dir_ / "tiny.gemdb";
    fs::remove(db);
    const Outcome build =
        run("build " + stone_.string() + " -o " + db.string() + " " + kTinyOptions);
    ASSERT_EQ(build.status, 0) << build.output;
    EXPECT_NE(build.output.find("pixel ray-lists/s"), std::string::npos) << build.output;
    ASSERT_TRUE(fs::exists(db));

    const Outcome info = run("info " + db.string());
    ASSERT_EQ(info.status, 0) << info.output;
    // The parameters given above come back.
    EXPECT_NE(info.output.find("levels 4 8, spacing 40.000°, min elevation 0.00°, depth 12"),
              std::string::npos)
        << info.output;
    EXPECT_NE(info.output.find("diamond"), std::string::npos) << info.output;
    EXPECT_NE(info.output.find("bytes/stored pixel"), std::string::npos) << info.output;

    const Outcome verify = run("verify " + db.string() + " --samples 500 --seed 7");
    ASSERT_EQ(verify.status, 0) << verify.output;
    EXPECT_NE(verify.output.find("re-traced 500 pixels"), std::string::npos) << verify.output;
    EXPECT_NE(verify.output.find(": OK"), std::string::npos) << verify.output;
}

// --budget chooses what --levels/--spacing/--depth/--threshold/--dispersion would set, so
// they are refused together; without --screen it cannot choose a level.
TEST_F(GemtablesCli, BudgetNeedsAScreenAndExcludesTheParametersItChooses) {
    const fs::path db = dir_ / "budget.gemdb";
    const std::string base = "build " + stone_.string() + " -o " + db.string() + " --budget 3";
    const Outcome no_screen = run(base);
    EXPECT_NE(no_screen.status, 0);
    EXPECT_NE(no_screen.output.find("--budget needs --screen"), std::string::npos)
        << no_screen.output;
    const Outcome both = run(base + " --screen 64 --depth 4");
    EXPECT_NE(both.status, 0);
    EXPECT_NE(both.output.find("excludes"), std::string::npos) << both.output;
    EXPECT_FALSE(fs::exists(db));

    const Outcome chosen = run(base + " --screen 32 --jump 4 --choose-only");
    ASSERT_EQ(chosen.status, 0) << chosen.output;
    EXPECT_NE(chosen.output.find("gemtables: chose spacing"), std::string::npos) << chosen.output;
    EXPECT_FALSE(fs::exists(db));  // --choose-only builds nothing
}

// The kiosk's background builds: --idle says what the kernel granted (read back with
// sched_getscheduler, not assumed), and the database is the same as without it; under a
// --memory-mb bound too small for the build, one message names the bound and no database
// appears.
TEST_F(GemtablesCli, IdleBuildsTheSameBytesAndAMemoryBoundFailsCleanly) {
    const fs::path plain = dir_ / "plain.gemdb";
    const fs::path idle = dir_ / "idle.gemdb";
    ASSERT_EQ(run("build " + stone_.string() + " -o " + plain.string() + " " + kTinyOptions).status,
              0);
    const Outcome built = run("build " + stone_.string() + " -o " + idle.string() + " " +
                              kTinyOptions + " --idle --memory-mb 1024");
    ASSERT_EQ(built.status, 0) << built.output;
    EXPECT_NE(built.output.find("running at idle CPU priority (SCHED_IDLE), nice 19"),
              std::string::npos)
        << built.output;
    EXPECT_EQ(tables_test::read_bytes(idle), tables_test::read_bytes(plain));

    // 16 MB of address space cannot hold the tracer's threads and tables.
    if (built.output.find("--memory-mb not applied") != std::string::npos) {
        GTEST_SKIP() << "a sanitizer build applies no address-space limit: " << built.output;
    }
    const fs::path starved = dir_ / "starved.gemdb";
    const Outcome failed = run("build " + stone_.string() + " -o " + starved.string() +
                               " --levels 64,128 --spacing 40 --jobs 2 --memory-mb 16");
    EXPECT_NE(failed.status, 0) << failed.output;
    EXPECT_NE(failed.output.find("--memory-mb"), std::string::npos) << failed.output;
    EXPECT_EQ(failed.output.find("terminate called"), std::string::npos) << failed.output;
    EXPECT_FALSE(fs::exists(starved));
}

// A piece sizes the stones it names (width_mm); tables built with the same width hold the
// piece's stone to the last bit, so the frame renderer draws it from them (piece_tables.hpp).
TEST_F(GemtablesCli, TablesBuiltAtAPiecesWidthHoldThePiecesStone) {
    write_text(dir_ / "ring.toml",
               "[piece]\nname = \"ring\"\nsetting = \"solitaire\"\n\n[centre]\nstone = "
               "\"tiny.toml\"\nwidth_mm = 3.0\n");
    auto piece = load_piece(dir_ / "ring.toml");
    ASSERT_TRUE(piece) << piece.error();
    const char* options = "--levels 4 --spacing 50 --min-elevation -90 --jobs 2";
    const fs::path sized = dir_ / "sized.gemdb";
    const fs::path unsized = dir_ / "unsized.gemdb";
    const Outcome built =
        run("build " + stone_.string() + " -o " + sized.string() + " --width-mm 3 " + options);
    ASSERT_EQ(built.status, 0) << built.output;
    ASSERT_EQ(run("build " + stone_.string() + " -o " + unsized.string() + " " + options).status,
              0);
    auto a = Database::open(sized);
    auto b = Database::open(unsized);
    ASSERT_TRUE(a && b);
    EXPECT_TRUE(same_stored_stone(a.value().stone(), piece.value().kinds[0]));
    EXPECT_FALSE(same_stored_stone(b.value().stone(), piece.value().kinds[0]));
    // The width is the stone's girdle width, as a jeweller measures it.
    EXPECT_NEAR(girdle_width(a.value().stone()), 3.0, 1e-9);
}

TEST_F(GemtablesCli, VerifyFailsOnDamagedCopies) {
    const fs::path db = dir_ / "tiny.gemdb";
    ASSERT_EQ(run("build " + stone_.string() + " -o " + db.string() + " " + kTinyOptions).status,
              0);
    const std::vector<std::uint8_t> good = tables_test::read_bytes(db);
    ASSERT_GT(good.size(), 100u);

    // A payload byte near the end: the file opens, one table fails its checksum.
    std::vector<std::uint8_t> payload = good;
    payload[payload.size() - 3] ^= 0x10;
    tables_test::write_bytes(dir_ / "payload.gemdb", payload);
    const Outcome a = run("verify " + (dir_ / "payload.gemdb").string() + " --samples 10");
    EXPECT_NE(a.status, 0) << a.output;
    EXPECT_NE(a.output.find("checksum mismatch"), std::string::npos) << a.output;
    EXPECT_NE(a.output.find("1 damaged"), std::string::npos) << a.output;

    // A header byte: the file does not open at all.
    std::vector<std::uint8_t> header = good;
    header[20] ^= 0x01;
    tables_test::write_bytes(dir_ / "header.gemdb", header);
    const Outcome b = run("verify " + (dir_ / "header.gemdb").string());
    EXPECT_NE(b.status, 0) << b.output;
    EXPECT_NE(b.output.find("header.gemdb"), std::string::npos) << b.output;

    const Outcome c = run("info " + (dir_ / "header.gemdb").string());
    EXPECT_NE(c.status, 0) << c.output;
}

TEST_F(GemtablesCli, BadStoneFilesNameFileLineAndKey) {
    const fs::path out = dir_ / "never.gemdb";
    fs::remove(out);
    const fs::path wrong_type = write_text(
        dir_ / "wrong_type.toml", "[stone]\ncut = \"round\"\ncrown_angle_deg = \"steep\"\n");
    const Outcome a = run("build " + wrong_type.string() + " -o " + out.string());
    EXPECT_NE(a.status, 0);
    EXPECT_NE(a.output.find(wrong_type.string() + ":3: stone.crown_angle_deg: expected a number"),
              std::string::npos)
        << a.output;

    const fs::path unknown =
        write_text(dir_ / "unknown.toml", "[stone]\ncut = \"round\"\n\n[camera]\nzoom = 2.0\n");
    const Outcome b = run("build " + unknown.string() + " -o " + out.string());
    EXPECT_NE(b.status, 0);
    EXPECT_NE(b.output.find(unknown.string() + ":4: camera: unknown key"), std::string::npos)
        << b.output;

    const fs::path syntax =
        write_text(dir_ / "syntax.toml", "[stone]\ncut = \"round\"\nwidth_mm = \n");
    const Outcome c = run("build " + syntax.string() + " -o " + out.string());
    EXPECT_NE(c.status, 0);
    EXPECT_NE(c.output.find(syntax.string() + ":3:"), std::string::npos) << c.output;

    const fs::path bad_cut = write_text(dir_ / "bad_cut.toml", "[stone]\ncut = \"trillion\"\n");
    const Outcome d = run("build " + bad_cut.string() + " -o " + out.string());
    EXPECT_NE(d.status, 0);
    EXPECT_NE(d.output.find(bad_cut.string() + ":2: stone.cut: unknown cut 'trillion'"),
              std::string::npos)
        << d.output;

    const Outcome e = run("build " + (dir_ / "missing.toml").string() + " -o " + out.string());
    EXPECT_NE(e.status, 0);
    EXPECT_NE(e.output.find("missing.toml: no such file"), std::string::npos) << e.output;

    const Outcome f = run("build " + stone_.string() + " -o " + out.string() + " --levels 8,4");
    EXPECT_NE(f.status, 0);
    EXPECT_NE(f.output.find("--levels"), std::string::npos) << f.output;
    EXPECT_FALSE(fs::exists(out));
}

TEST_F(GemtablesCli, OutputAppearsOnlyComplete) {
    const fs::path db = dir_ / "atomic.gemdb";
    fs::remove(db);
    // Slow enough (one job, a few thousand pixels per view) to be watched while it runs.
    const std::string command = std::string(GEMTABLES_PATH) + " build " + stone_.string() + " -o " +
                                db.string() +
                                " --levels 32,64 --spacing 25 --min-elevation 0 --jobs 1 2>&1";
    std::FILE* pipe = ::popen(command.c_str(), "r");
    ASSERT_NE(pipe, nullptr);
    std::thread drain([&] {
        char buffer[256];
        while (std::fread(buffer, 1, sizeof buffer, pipe) > 0) {
        }
    });
    std::vector<std::uint8_t> first_sight;
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    while (std::chrono::steady_clock::now() < give_up) {
        if (fs::exists(db)) {
            // The moment the name appears, take what is under it.
            first_sight = tables_test::read_bytes(db);
            break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    drain.join();
    const int raw = ::pclose(pipe);
    ASSERT_TRUE(WIFEXITED(raw) && WEXITSTATUS(raw) == 0);
    // What first showed under the name was the whole file: byte for byte the final one, which
    // opens (every section and the index check out). Whether the poll also caught the
    // temporary file depends on timing, so it is not asserted.
    EXPECT_EQ(first_sight, tables_test::read_bytes(db));
    EXPECT_TRUE(Database::open(db).ok());
    for (const auto& entry : fs::directory_iterator(dir_)) {
        EXPECT_FALSE(entry.path().filename().string().starts_with("atomic.gemdb.tmp"))
            << entry.path();
    }
}

TEST_F(GemtablesCli, BuildsAreDeterministicAcrossJobCounts) {
    const std::string base = "build " + stone_.string() + " --levels 4,8 --spacing 40 ";
    ASSERT_EQ(run(base + "-o " + (dir_ / "one.gemdb").string() + " --jobs 1").status, 0);
    ASSERT_EQ(run(base + "-o " + (dir_ / "three.gemdb").string() + " --jobs 3").status, 0);
    EXPECT_EQ(tables_test::read_bytes(dir_ / "one.gemdb"),
              tables_test::read_bytes(dir_ / "three.gemdb"));
}

TEST_F(GemtablesCli, InspectWritesBothPictures) {
    const fs::path db = dir_ / "tiny.gemdb";
    ASSERT_EQ(run("build " + stone_.string() + " -o " + db.string() + " " + kTinyOptions).status,
              0);
    const fs::path prefix = dir_ / "face-up";
    const Outcome r =
        run("inspect " + db.string() + " --view-direction 0,90 -o " + prefix.string());
    ASSERT_EQ(r.status, 0) << r.output;
    auto shaded = read_png(prefix.string() + "-shaded.png");
    auto lengths = read_png(prefix.string() + "-raylist-length.png");
    ASSERT_TRUE(shaded.ok() && lengths.ok());
    // The finest level is 8 pixels a side; the window is 5 % wider than the stone's bounding
    // sphere, so a corner misses (black) and the centre hits (coloured).
    EXPECT_EQ(lengths.value().width, 8);
    EXPECT_EQ(lengths.value().height, 8);
    EXPECT_EQ(shaded.value().width, 8);
    const glm::vec4 corner = lengths.value().at(0, 0);
    const glm::vec4 centre = lengths.value().at(4, 4);
    EXPECT_EQ(glm::vec3(corner), glm::vec3(0.0f));
    EXPECT_GT(centre.x + centre.y + centre.z, 0.5f);

    const Outcome bad =
        run("inspect " + db.string() + " --view-direction 0,90 --level 5 -o " + prefix.string());
    EXPECT_NE(bad.status, 0);
    EXPECT_NE(bad.output.find("--level 5"), std::string::npos) << bad.output;
}

TEST_F(GemtablesCli, ACatalogueOfDesignsHasTablesOnlyWhereTheyPay) {
    const fs::path designs = dir_ / "designs";
    const fs::path out = dir_ / "catalogue";
    fs::remove_all(designs);
    fs::remove_all(out);
    fs::create_directories(designs);
    const fs::path models = fs::path(GEM_FIXTURES_DIR) / "models";
    fs::copy_file(models / "square_step.asc", designs / "square_step.asc");  // convex
    fs::copy_file(models / "l_prism.obj", designs / "l_prism.obj");          // not convex
    write_text(designs / "broken.toml", "[stone]\ncut = \"round\"\nwidth_mm = -2\n");
    const Outcome made = run("catalogue " + designs.string() + " -o " + out.string() +
                             " --name spring --material sapphire " + kTinyOptions);
    ASSERT_EQ(made.status, 0) << made.output;
    // A line per design, the broken one named with its own file and fault.
    EXPECT_NE(made.output.find("1/3 broken.toml: left out: " + (designs / "broken.toml").string() +
                               ":3: stone.width_mm"),
              std::string::npos)
        << made.output;
    EXPECT_NE(made.output.find("2/3 l_prism.obj: not convex"), std::string::npos) << made.output;
    EXPECT_NE(made.output.find("3/3 square_step.asc: convex"), std::string::npos) << made.output;

    std::ifstream in(out / "catalogue.toml");
    std::stringstream manifest;
    manifest << in.rdbuf();
    const std::string text = manifest.str();
    EXPECT_NE(text.find("name = \"spring\""), std::string::npos) << text;
    EXPECT_NE(text.find("database = \"l_prism.gemdb\""), std::string::npos) << text;
    EXPECT_NE(text.find("design = \"square_step.toml\""), std::string::npos) << text;
    EXPECT_EQ(text.find("broken"), std::string::npos) << text;
    // The model's description names the model beside it and the material asked for.
    std::ifstream described(out / "square_step.toml");
    std::stringstream description;
    description << described.rdbuf();
    EXPECT_NE(description.str().find("model = \"square_step.asc\""), std::string::npos);
    EXPECT_NE(description.str().find("name = \"sapphire\""), std::string::npos);
    EXPECT_TRUE(fs::exists(out / "square_step.asc"));
    // The tables it did build are sound.
    const Outcome verified = run("verify " + (out / "l_prism.gemdb").string() + " --samples 50");
    EXPECT_EQ(verified.status, 0) << verified.output;
}

TEST_F(GemtablesCli, ACatalogueWithoutOneReadableDesignIsRefused) {
    const fs::path designs = dir_ / "designs";
    fs::remove_all(designs);
    fs::create_directories(designs);
    write_text(designs / "broken.toml", "[stone]\ncut = \"dodecahedron\"\n");
    const Outcome made = run("catalogue " + designs.string() + " -o " + (dir_ / "out").string());
    EXPECT_EQ(made.status, 1) << made.output;
    EXPECT_NE(made.output.find("gemtables: no design could be read"), std::string::npos)
        << made.output;
    EXPECT_FALSE(fs::exists(dir_ / "out" / "catalogue.toml"));
}

}  // namespace
}  // namespace gem
