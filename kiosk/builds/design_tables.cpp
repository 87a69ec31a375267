#include "builds/design_tables.hpp"

#include <xxhash.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <system_error>

#include "catalogue/payload_checksums.hpp"
#include "gemdb/bytes.hpp"
#include "gemdb/format.hpp"
#include "gemdb/sections.hpp"
#include "probe/method_probe.hpp"
#include "service/log.hpp"
#include "service/process_info.hpp"
#include "util/atomic_file.hpp"

namespace gem::kiosk {

namespace {

namespace fs = std::filesystem;

// Frames after a scene is made that are not timed: the first draws compile the shaders.
constexpr int kWarmupFrames = 2;
// Frames timed per method; judged by their 90th percentile, as the method probe judges.
constexpr std::size_t kTimedFrames = 6;

std::string fixed(double value, int decimals) {
    char text[32];
    std::snprintf(text, sizeof text, "%.*f", decimals, value);
    return text;
}

}  // namespace

std::vector<TabledStone> tabled_stones(const CatalogueStone& entry) {
    std::vector<TabledStone> out;
    if (!entry.design.empty() && entry.designed != nullptr) {
        out.push_back(
            {0, "design '" + entry.name + "'", entry.design, 0.0, false, entry.designed.get()});
        return out;
    }
    if (entry.placed == nullptr) return out;
    const Piece& piece = *entry.placed;
    if (piece.kind_sources.size() != piece.kinds.size()) return out;  // made in code
    for (std::size_t k = 0; k < piece.kinds.size(); ++k) {
        const Stone& stone = piece.kinds[k];
        // A convex stone is traced by its planes or its walk, as cheap as its tables.
        if (stone.convex) continue;
        const KindSource& source = piece.kind_sources[k];
        std::string size;
        if (source.width_mm > 0.0) size = fixed(source.width_mm, 1) + " mm ";
        out.push_back({k, "piece '" + entry.name + "': its " + size + "stone '" + stone.name + "'",
                       source.description, source.width_mm, true, &stone});
    }
    return out;
}

DesignTables::DesignTables(DesignsConfig config, fs::path dir)
    : config_(std::move(config)), dir_(std::move(dir)) {}

DesignTables::~DesignTables() {
    const bool was_building = build_ != nullptr;
    build_.reset();  // stops it
    if (was_building) drop_stale_temporaries();
    if (check_.valid()) check_.wait();
}

std::string DesignTables::key_of(const TabledStone& stone) const {
    // What the tables depend on: the stone and material as a database stores them, the
    // build settings and the format.
    ByteWriter bytes;
    write_stone_identity(bytes, *stone.stone);
    bytes.u16(gemdb::kVersionMajor);
    bytes.u16(gemdb::kVersionMinor);
    bytes.u32(static_cast<std::uint32_t>(config_.level_px));
    bytes.f64(config_.spacing_deg);
    bytes.u32(static_cast<std::uint32_t>(config_.depth));
    bytes.f64(config_.threshold);
    // A piece's stone stores every direction; a design's, the elevations from −10° up.
    if (stone.whole_sphere) bytes.u8(1);
    char key[24];
    std::snprintf(key, sizeof key, "%016llx",
                  static_cast<unsigned long long>(XXH64(bytes.bytes().data(), bytes.size(), 0)));
    return key;
}

const std::vector<DesignTables::Keyed>& DesignTables::keyed(const CatalogueStone& stone) const {
    static const std::vector<Keyed> none;
    std::shared_ptr<const void> owner = stone.designed;
    if (!owner) owner = stone.placed;
    if (!owner) return none;
    if (owner.get() == keyed_address_ && !keyed_owner_.expired()) return keyed_;
    keyed_.clear();
    for (TabledStone& t : tabled_stones(stone)) {
        std::string key = key_of(t);
        keyed_.push_back({std::move(t), std::move(key)});
    }
    keyed_owner_ = owner;
    keyed_address_ = owner.get();
    return keyed_;
}

fs::path DesignTables::file_of(const std::string& key, const char* extension) const {
    return dir_ / (key + extension);
}

fs::path DesignTables::tables_path(const CatalogueStone& stone) const {
    const std::vector<Keyed>& k = keyed(stone);
    return k.empty() ? fs::path() : file_of(k.front().key, ".gemdb");
}

DesignTables::KindTables DesignTables::tables_for(const CatalogueStone& stone) const {
    KindTables tables;
    for (const Keyed& k : keyed(stone)) {
        const auto found = entries_.find(k.key);
        if (found == entries_.end() || found->second.state != State::tables) continue;
        if (tables.size() <= k.stone.kind) tables.resize(k.stone.kind + 1);
        tables[k.stone.kind] = found->second.database;
    }
    return tables;
}

DesignTables::Entry& DesignTables::entry_for(const Keyed& keyed) {
    Entry& e = entries_[keyed.key];
    if (e.state == State::unknown) {
        e.who = keyed.stone.who;
        e.design = keyed.stone.description;
        e.width_mm = keyed.stone.width_mm;
        e.whole_sphere = keyed.stone.whole_sphere;
        e.dispersion = keyed.stone.stone->material.disperses();
        look_on_disk(keyed.key, e);
    }
    return e;
}

void DesignTables::look_on_disk(const std::string& key, Entry& e) {
    const std::string& who = e.who;
    std::error_code ec;
    if (config_.tables == DesignTablesMode::never) {
        e.state = State::trace_holds;
        return;
    }
    if (config_.tables == DesignTablesMode::automatic && fs::exists(file_of(key, ".trace"), ec)) {
        e.state = State::trace_wins;
        log_info(who + ": its tables did not pay on this machine (" +
                 file_of(key, ".trace").string() + "): drawn by the trace");
        return;
    }
    const bool built = fs::exists(file_of(key, ".gemdb"), ec);
    // Tables whose verdict was not reached (the kiosk stopped first) are timed again against
    // the trace before they are trusted.
    const bool judged =
        config_.tables != DesignTablesMode::automatic || fs::exists(file_of(key, ".pays"), ec);
    if (built && judged) {
        log_info(who + ": checking the tables built before, " + file_of(key, ".gemdb").string());
        e.state = State::checking;
        return;
    }
    if (config_.tables == DesignTablesMode::always) {
        e.state = State::waiting;
        queue_.push_back(key);
        log_info(who + ": its tables will be built in the background (designs.tables = always)");
        return;
    }
    e.state = State::measuring;
    e.trace_ms.reserve(kTimedFrames);
}

void DesignTables::frame_drawn(const CatalogueStone& stone, const KindTables& drawn,
                               int frames_since_scene, double draw_ms, double budget_ms) {
    if (frames_since_scene < kWarmupFrames) return;
    for (const Keyed& k : keyed(stone)) {
        const bool from_tables = k.stone.kind < drawn.size() && drawn[k.stone.kind] != nullptr;
        judge_frame(entry_for(k), k.key, from_tables, draw_ms, budget_ms);
    }
}

void DesignTables::judge_frame(Entry& e, const std::string& key, bool from_tables, double draw_ms,
                               double budget_ms) {
    if (e.state == State::measuring && !from_tables) {
        e.trace_ms.push_back(draw_ms);
        if (e.trace_ms.size() < kTimedFrames) return;
        const std::optional<double> p90 = frame_time_statistic_ms(e.trace_ms);
        e.trace_ms.clear();
        if (!p90) return;  // no usable frame: time it again
        e.trace_p90_ms = *p90;
        const std::string& who = e.who;
        if (!(*p90 > budget_ms)) {
            e.state = State::trace_holds;
            log_info(who + ": the trace holds the frame budget (p90 " + fixed(*p90, 1) +
                     " ms, budget " + fixed(budget_ms, 1) + " ms): no tables");
            return;
        }
        const std::string over_budget = who + ": the trace draws it in p90 " + fixed(*p90, 1) +
                                        " ms, over the " + fixed(budget_ms, 1) + " ms budget: ";
        std::error_code ec;
        if (fs::exists(file_of(key, ".gemdb"), ec)) {
            // Built by an earlier run that stopped before timing them.
            e.state = State::checking;
            log_notice(over_budget + "checking the tables built before, " +
                       file_of(key, ".gemdb").string());
            return;
        }
        e.state = State::waiting;
        queue_.push_back(key);
        log_notice(over_budget + "building its tables in the background");
        return;
    }
    if (e.state == State::tables && e.fresh && from_tables) {
        e.table_ms.push_back(draw_ms);
        if (e.table_ms.size() < kTimedFrames) return;
        const std::optional<double> p90 = frame_time_statistic_ms(e.table_ms);
        e.table_ms.clear();
        if (!p90) return;
        e.fresh = false;
        const std::string& who = e.who;
        const std::string figures =
            "p90 " + fixed(*p90, 1) + " ms against the trace's " + fixed(e.trace_p90_ms, 1) + " ms";
        // The verdict is kept beside the tables, so that a later run trusts them, or builds
        // them no more.
        const std::string verdict = "tables " + figures + "\n";
        const bool pay = *p90 < e.trace_p90_ms;
        if (auto written = write_file_atomic(file_of(key, pay ? ".pays" : ".trace"), verdict.data(),
                                             verdict.size());
            !written) {
            log_warning(who + ": " + written.error());
        }
        if (pay) {
            log_notice(who + ": its tables pay: " + figures);
            return;
        }
        // Slower than the trace: the trace stays, and the tables themselves go.
        std::error_code ec;
        e.database.reset();
        fs::remove(file_of(key, ".gemdb"), ec);
        fs::remove(file_of(key, ".pays"), ec);
        e.state = State::trace_wins;
        switched_key_ = key;
        log_notice(who + ": its tables do not pay here (" + figures +
                   "): drawn by the trace, and not built again");
    }
}

bool DesignTables::dispatch(const CatalogueStone* shown) {
    take_build_output();
    take_check();
    if (shown != nullptr) {
        for (const Keyed& k : keyed(*shown)) entry_for(k);
    }
    if (!build_) start_next_build();
    if (!check_.valid()) {
        // Tables found on disk, or just built, wait for their check one at a time.
        for (auto& [key, e] : entries_) {
            if (e.state == State::checking) {
                start_check(key, file_of(key, ".gemdb"));
                break;
            }
        }
    }
    bool switched = false;
    if (!switched_key_.empty() && shown != nullptr) {
        for (const Keyed& k : keyed(*shown)) switched = switched || k.key == switched_key_;
    }
    switched_key_.clear();
    return switched;
}

void DesignTables::start_check(const std::string& key, const fs::path& file) {
    check_key_ = key;
    check_ = std::async(std::launch::async, [file] { return open_intact_database(file); });
}

void DesignTables::take_check() {
    if (!check_.valid() || check_.wait_for(std::chrono::seconds(0)) != std::future_status::ready) {
        return;
    }
    Result<std::shared_ptr<const Database>> checked = check_.get();
    Entry& e = entries_[check_key_];
    const std::string& who = e.who;
    if (checked) {
        e.state = State::tables;
        e.database = std::move(checked).value();
        // Fresh tables in auto mode are timed against the trace before they are trusted.
        e.fresh = config_.tables == DesignTablesMode::automatic && e.trace_p90_ms > 0.0;
        e.table_ms.reserve(kTimedFrames);
        switched_key_ = check_key_;
        log_notice(who + ": drawn from its tables, " + e.database->path().string());
        return;
    }
    std::error_code ec;
    fs::remove(file_of(check_key_, ".gemdb"), ec);
    if (e.build_started_s > 0.0) {
        // Just built and already damaged: building again would likely end the same way.
        e.state = State::failed;
        log_error(who + ": its new tables do not check (" + checked.error() +
                  "); removed; it stays drawn by the trace");
        return;
    }
    log_warning(who + ": its tables do not check (" + checked.error() + "); removed");
    e.state = State::unknown;
    look_on_disk(check_key_, e);
}

void DesignTables::start_next_build() {
    while (!queue_.empty()) {
        const std::string key = queue_.front();
        queue_.erase(queue_.begin());
        Entry& e = entries_[key];
        if (e.state != State::waiting) continue;
        const std::string& who = e.who;
        std::error_code ec;
        fs::create_directories(dir_, ec);
        if (ec) {
            e.state = State::failed;
            log_error(who + ": its tables cannot be built: " + dir_.string() + ": " + ec.message() +
                      "; it stays drawn by the trace");
            continue;
        }
        drop_stale_temporaries();
        std::vector<std::string> argv = {
            config_.builder.string(),
            "build",
            e.design.string(),
            "-o",
            file_of(key, ".gemdb").string(),
            "--levels",
            std::to_string(config_.level_px / 2) + "," + std::to_string(config_.level_px),
            "--spacing",
            fixed(config_.spacing_deg, 3),
            "--depth",
            std::to_string(config_.depth),
            "--threshold",
            fixed(config_.threshold, 6),
            "--idle",
            "--memory-mb",
            std::to_string(config_.memory_mb)};
        if (e.dispersion) argv.push_back("--dispersion");
        if (e.width_mm > 0.0) {
            argv.push_back("--width-mm");
            // Every digit: the builder must size the stone to the piece's very bits.
            char width[32];
            std::snprintf(width, sizeof width, "%.17g", e.width_mm);
            argv.push_back(width);
        }
        if (e.whole_sphere) {
            argv.push_back("--min-elevation");
            argv.push_back("-90");
        }
        if (config_.jobs > 0) {
            argv.push_back("--jobs");
            argv.push_back(std::to_string(config_.jobs));
        }
        auto started = ChildProcess::start(argv);
        if (!started) {
            e.state = State::failed;
            log_error(who + ": its tables cannot be built: " + started.error() +
                      "; it stays drawn by the trace");
            continue;
        }
        build_ = std::move(started).value();
        build_key_ = key;
        build_last_line_.clear();
        e.state = State::building;
        e.build_started_s = monotonic_now_s();
        log_info(who + ": building its tables (pid " + std::to_string(build_->pid()) + ", into " +
                 file_of(key, ".gemdb").string() + ")");
        return;
    }
}

void DesignTables::take_build_output() {
    if (!build_) return;
    Entry& e = entries_[build_key_];
    for (const std::string& line : build_->read_lines()) {
        // Its progress every tenth is for a debugging eye; the rest says what it does.
        const bool progress = line.find(" tables), elapsed ") != std::string::npos;
        log(progress ? LogLevel::debug : LogLevel::info, e.who + ": " + line);
        build_last_line_ = line;
    }
    if (!build_->ended()) return;
    const std::string& who = e.who;
    const bool ok = build_->succeeded();
    const std::string end = build_->describe_end();
    build_.reset();
    std::error_code ec;
    if (ok && fs::exists(file_of(build_key_, ".gemdb"), ec)) {
        log_info(who + ": tables built in " + fixed(monotonic_now_s() - e.build_started_s, 1) +
                 " s; checking them");
        e.state = State::checking;
        return;
    }
    drop_stale_temporaries();
    e.state = State::failed;
    log_error(who + ": its tables could not be built (the builder " + end +
              (build_last_line_.empty() ? std::string() : ": " + build_last_line_) +
              "); it stays drawn by the trace");
}

void DesignTables::drop_stale_temporaries() const {
    // A build stopped or killed leaves its AtomicFile temporary (<key>.gemdb.tmp-<pid>).
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(dir_, ec)) {
        const std::string name = entry.path().filename().string();
        if (name.find(".gemdb.tmp-") != std::string::npos) fs::remove(entry.path(), ec);
    }
}

}  // namespace gem::kiosk
