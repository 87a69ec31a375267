#include "catalogue_test_support.hpp"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <iterator>
#include <numbers>
#include <sstream>
#include <thread>

#include <gtest/gtest.h>

#include "geometry/cuts.hpp"
#include "optics/material.hpp"
#include "table_build.hpp"

namespace gem::kiosk::catalogue_test {

namespace fs = std::filesystem;

fs::path fresh_dir(const std::string& name) {
    const fs::path dir = fs::path(GEM_ARTIFACT_DIR) / "catalogue" / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

const fs::path& tiny_database() {
    static const fs::path path = [] {
        const fs::path p = fs::path(GEM_ARTIFACT_DIR) / "catalogue-tiny.gemdb";
        auto stone =
            make_cut(default_cut_params(CutShape::round_brilliant), *find_material("diamond"));
        EXPECT_TRUE(stone.ok());
        BuildParams params;
        params.levels = {32};
        params.grid.spacing_rad = 40.0 * std::numbers::pi / 180.0;
        params.grid.min_elevation_rad = -10.0 * std::numbers::pi / 180.0;
        params.max_depth = 4;
        auto grid = ViewGrid::build(params.grid, stone.value().symmetry);
        EXPECT_TRUE(grid.ok());
        fs::create_directories(p.parent_path());
        auto written = tables::trace_and_write(p, stone.value(), params, grid.value(), 2);
        EXPECT_TRUE(written.ok()) << written.error();
        return p;
    }();
    return path;
}

std::vector<std::uint8_t> read_bytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_bytes(const fs::path& path, const std::vector<std::uint8_t>& bytes) {
    fs::create_directories(path.parent_path());
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(bytes.data()),
              static_cast<std::streamsize>(bytes.size()));
}

void write_text(const fs::path& path, const std::string& text) {
    fs::create_directories(path.parent_path());
    std::ofstream out(path, std::ios::trunc);
    out << text;
}

std::string read_text(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

std::string copy_shipped_halo(const fs::path& dir) {
    const fs::path config = fs::path(GEM_SOURCE_DIR) / "config";
    fs::create_directories(dir / "stones");
    for (const char* stone : {"tolkowsky-diamond.toml", "melee-diamond.toml"}) {
        fs::copy_file(config / "stones" / stone, dir / "stones" / stone);
    }
    const std::string halo = read_text(config / "pieces" / "halo.toml");
    write_text(dir / "pieces" / "halo.toml", halo);
    return halo;
}

std::string run_command(const std::string& command, int* status) {
    std::string out;
    FILE* pipe = ::popen((command + " 2>&1").c_str(), "r");
    if (pipe == nullptr) return out;
    char buffer[4096];
    std::size_t got = 0;
    while ((got = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) out.append(buffer, got);
    const int rc = ::pclose(pipe);
    if (status != nullptr) *status = WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
    return out;
}

std::string one_stone_manifest(const std::string& name) {
    return "[catalogue]\nname = \"" + name +
           "\"\n\n[[stone]]\nname = \"Round\"\ndatabase = \"stones/round.gemdb\"\n";
}

void write_catalogue(const fs::path& dir, const std::string& name) {
    // The database is read (and on first use built, seconds under a sanitizer) before the
    // manifest lands, so the two files arrive well within the watcher's settle time.
    const std::vector<std::uint8_t> database = read_bytes(tiny_database());
    write_text(dir / "catalogue.toml", one_stone_manifest(name));
    write_bytes(dir / "stones" / "round.gemdb", database);
}

namespace {

std::uint64_t get(const std::vector<std::uint8_t>& b, std::size_t at, int bytes) {
    std::uint64_t v = 0;
    for (int i = 0; i < bytes; ++i) v |= static_cast<std::uint64_t>(b.at(at + i)) << (8 * i);
    return v;
}

}  // namespace

std::uint32_t header_view_count(const std::vector<std::uint8_t>& file) {
    // Header: magic 8, major 2, minor 2, flags 4, header bytes 4, sections 4, file bytes 8,
    // views 4 (byte 32), levels 4, reserved 8.
    return static_cast<std::uint32_t>(get(file, 32, 4));
}

PayloadSpan payload_span(const std::vector<std::uint8_t>& file, std::uint32_t view,
                         std::uint32_t level, std::uint32_t levels) {
    const auto sections = get(file, 20, 4);
    for (std::uint64_t s = 0; s < sections; ++s) {
        const std::size_t record = 48 + 32 * s;
        if (get(file, record, 4) != 6) continue;
        const std::size_t index = get(file, record + 8, 8);
        const std::size_t entry = index + 32 * (std::size_t{view} * levels + level);
        return {get(file, entry, 8), static_cast<std::uint32_t>(get(file, entry + 8, 4))};
    }
    ADD_FAILURE() << "no index section";
    return {};
}

StderrCapture::StderrCapture() {
    path_ = fs::path(GEM_ARTIFACT_DIR) / ("stderr-" + std::to_string(::getpid()) + ".txt");
    std::fflush(stderr);
    saved_ = ::dup(2);
    const int fd = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    ::dup2(fd, 2);
    ::close(fd);
}

StderrCapture::~StderrCapture() {
    ::dup2(saved_, 2);
    ::close(saved_);
    // Show what was captured, so a failing test still has its log.
    const std::string captured = text();
    [[maybe_unused]] const ssize_t n = ::write(2, captured.data(), captured.size());
}

std::string StderrCapture::text() const {
    std::ifstream in(path_);
    std::ostringstream all;
    all << in.rdbuf();
    return all.str();
}

bool wait_until(const std::function<bool()>& done) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (std::chrono::steady_clock::now() < end) {
        if (done()) return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return done();
}

}  // namespace gem::kiosk::catalogue_test
