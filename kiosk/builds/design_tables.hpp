#pragma once
// Tables for the designs in a catalogue (catalogue.hpp: a stone that names a stone description
// instead of a database) and for the non-convex stones of its pieces (a heart in a three-stone
// ring: traced as its convex pieces, or through its triangles where it does not split into
// few, it costs more per pixel than a convex stone). Such
// a stone is shown at once by the exact trace; its tables are built in the background when they
// pay, and switched to between two frames (a piece's frame is timed whole, each of its
// non-convex kinds judged by it; their tables store every direction, sized as the piece sizes
// the stone: gpu/piece_tables.hpp):
//
//   measuring   its trace frames are timed (six, after the first two, which compile shaders,
//               judged by their 90th percentile as the method probe judges); within the frame
//               budget the trace stays and nothing is built
//   building    `gemtables build --idle --memory-mb N` runs as a child process: idle CPU
//               priority, so it takes only time no frame wants; bounded address space; the file
//               appears atomically in the tables folder. One build at a time, in the order the
//               designs asked for one
//   checking    the finished (or, after a restart, the found) database is opened and every
//               view's checksum verified, on a worker thread
//   tables      drawn from its tables; with mode auto, fresh tables are timed as the trace was
//               and kept only if they are faster. The verdict is written beside them: <key>.pays,
//               so a later run trusts them, or <key>.trace (and the tables go), so no later run
//               builds them again. Tables without a verdict (the kiosk stopped first) are timed
//               again, after the trace, in the next run
//
// Files are named by a hash of the stone (geometry and material, the sections a database
// stores) and the build settings, so a changed design or setting builds anew, a catalogue
// installed again finds the tables it had, and a restart reuses them. A build that fails gets
// one error line with the builder's own last line; the design stays drawn by the trace.

#include <cstdint>
#include <filesystem>
#include <future>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "builds/child_process.hpp"
#include "catalogue/catalogue.hpp"
#include "gemdb/reader.hpp"
#include "settings/kiosk_config.hpp"

namespace gem::kiosk {

// A stone whose tables the kiosk can build: a design entry's stone (kind 0), or a piece's
// non-convex stone (its kind).
struct TabledStone {
    std::size_t kind = 0;
    std::string who;  // for log lines: "design 'Heart'", "piece 'Trio': its 4 mm stone 'heart'"
    std::filesystem::path description;
    double width_mm = 0.0;         // > 0: sized to this girdle width, as the piece sizes it
    bool whole_sphere = false;     // a piece turns its stones every way: every direction stored
    const Stone* stone = nullptr;  // the entry's design or piece keeps it
};

// The stones of `entry` tables can serve: a design's one stone; a piece's non-convex stones that
// came from a description; none for a database.
std::vector<TabledStone> tabled_stones(const CatalogueStone& entry);

class DesignTables {
  public:
    // `dir`: where tables are kept (state_dir/tables); made when the first build starts.
    DesignTables(DesignsConfig config, std::filesystem::path dir);
    ~DesignTables();  // a running build is stopped; its partial file removed
    DesignTables(const DesignTables&) = delete;
    DesignTables& operator=(const DesignTables&) = delete;

    // The tables to draw `stone`'s kinds with, by kind (a design's one stone is kind 0), null
    // where the trace draws it; empty when no kind has tables (also for a database).
    using KindTables = std::vector<std::shared_ptr<const Database>>;
    KindTables tables_for(const CatalogueStone& stone) const;

    // A frame of `stone` was drawn in `draw_ms` with `drawn` (what tables_for gave its scene);
    // `frames_since_scene` counts the frames since its scene was made (the first compile).
    void frame_drawn(const CatalogueStone& stone, const KindTables& drawn, int frames_since_scene,
                     double draw_ms, double budget_ms);

    // Reads the running build's output, takes finished builds and checks, starts the next
    // ones. True when `shown`'s tables came into or went out of use since the last call: its
    // scene must be made again.
    bool dispatch(const CatalogueStone* shown);

    // Readable when the running build prints or ends; -1 when none runs.
    int fd() const { return build_ ? build_->fd() : -1; }
    // A build or a check is running: dispatch() wants calling now and then.
    bool busy() const { return build_ != nullptr || check_.valid(); }

    // The file the tables of `stone`'s first tabled stone are (or would be) kept in.
    std::filesystem::path tables_path(const CatalogueStone& stone) const;

  private:
    enum class State {
        unknown,
        measuring,
        trace_holds,
        waiting,
        building,
        checking,
        tables,
        trace_wins,
        failed
    };
    struct Entry {
        State state = State::unknown;
        std::string who;               // for log lines (TabledStone::who)
        std::filesystem::path design;  // the description the builder reads
        double width_mm = 0.0;         // > 0: the builder sizes the stone so
        bool whole_sphere = false;     // every direction stored
        bool dispersion = false;       // the material disperses: fire is stored
        bool fresh = false;            // built in this run: still to be timed (auto)
        std::vector<double> trace_ms;
        std::vector<double> table_ms;
        double trace_p90_ms = 0.0;
        std::shared_ptr<const Database> database;
        double build_started_s = 0.0;
    };

    // A tabled stone and the key its files are named by.
    struct Keyed {
        TabledStone stone;
        std::string key;
    };
    // `stone`'s tabled stones, keyed; the last entry's are kept, so the frames of one entry
    // list and hash them once.
    const std::vector<Keyed>& keyed(const CatalogueStone& stone) const;
    std::string key_of(const TabledStone& stone) const;
    Entry& entry_for(const Keyed& keyed);
    void judge_frame(Entry& e, const std::string& key, bool from_tables, double draw_ms,
                     double budget_ms);
    void look_on_disk(const std::string& key, Entry& entry);
    void start_check(const std::string& key, const std::filesystem::path& file);
    void take_check();
    void start_next_build();
    void take_build_output();
    void drop_stale_temporaries() const;
    std::filesystem::path file_of(const std::string& key, const char* extension) const;

    DesignsConfig config_;
    std::filesystem::path dir_;
    std::map<std::string, Entry> entries_;  // by key
    std::vector<std::string> queue_;        // keys waiting for a build, in order
    std::unique_ptr<ChildProcess> build_;
    std::string build_key_;
    std::string build_last_line_;
    std::future<Result<std::shared_ptr<const Database>>> check_;
    std::string check_key_;
    std::string switched_key_;  // an entry whose use of tables changed since dispatch()
    mutable std::weak_ptr<const void> keyed_owner_;  // the design or piece last listed
    mutable const void* keyed_address_ = nullptr;
    mutable std::vector<Keyed> keyed_;
};

}  // namespace gem::kiosk
