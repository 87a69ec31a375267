#include "gpu/piece_tables.hpp"

#include <numbers>
#include <string>

#include "gemdb/sections.hpp"
#include "gpu/table_method.hpp"

namespace gem::gpu {

namespace {

class PieceTables final : public StoneMethod {
  public:
    // tables[k]: kind k's table method, or null where `rest` draws it.
    PieceTables(std::unique_ptr<StoneMethod> rest, std::vector<std::unique_ptr<TableMethod>> tables,
                std::vector<std::vector<std::size_t>> stones_of_kind,
                std::vector<Placement> placements)
        : rest_(std::move(rest)),
          tables_(std::move(tables)),
          stones_of_kind_(std::move(stones_of_kind)),
          placements_(std::move(placements)) {
        // Sized once, and then assigned element by element (a frame's lights keep their
        // storage), so that a frame allocates nothing.
        std::size_t traced = 0;
        for (std::size_t k = 0; k < tables_.size(); ++k) {
            if (!tables_[k]) traced += stones_of_kind_[k].size();
        }
        rest_frames_.resize(traced);
        rest_kinds_.resize(traced);
        headings_.reserve(placements_.size());
    }

    void prepare(const Camera& camera, const glm::dvec3& omega, bool wait) override {
        rest_->prepare(camera, omega, wait);
        for (std::size_t k = 0; k < tables_.size(); ++k) {
            if (!tables_[k]) continue;
            headings_.clear();
            for (std::size_t i : stones_of_kind_[k]) {
                const Placement& at = placements_[i];
                headings_.push_back(
                    {at.direction_to_stone(-camera.forward()), at.direction_to_stone(omega)});
            }
            tables_[k]->prefetch(camera, headings_, wait);
        }
    }

    Result<bool> draw_depth(const std::vector<StoneFrame>& frames,
                            const std::vector<std::size_t>& kinds) override {
        select_rest(frames, kinds);
        // The tables' stones have no depth pass (table.frag discards where a view stores no
        // ray): they are drawn after the metal, tested against it and the traced stones.
        return rest_->draw_depth(rest_frames_, rest_kinds_);
    }

    Result<bool> draw(const std::vector<StoneFrame>& frames, const std::vector<std::size_t>& kinds,
                      FrameStats& stats) override {
        select_rest(frames, kinds);
        auto ok = rest_->draw(rest_frames_, rest_kinds_, stats);
        if (!ok) return ok;
        TableFrameStats sum;
        sum.drawn = true;
        sum.exact = true;
        sum.complete = true;
        for (std::size_t i = 0; i < frames.size(); ++i) {
            TableMethod* table = tables_[kinds[i]].get();
            if (table == nullptr) continue;
            TableFrameStats one;
            ok = table->draw(frames[i], &one);
            if (!ok) return ok;
            sum.acquire_ms += one.acquire_ms;
            sum.upload_ms += one.upload_ms;
            sum.wait_ms += one.wait_ms;
            sum.uploads += one.uploads;
            sum.level = std::max(sum.level, one.level);
            sum.exact = sum.exact && one.exact;
            sum.complete = sum.complete && one.complete;
            sum.drawn = sum.drawn && one.drawn;
            sum.angle_rad = std::max(sum.angle_rad, one.angle_rad);
            sum.views += one.views;
        }
        stats.table = sum;
        stats.stand_in = !sum.complete;
        return true;
    }

    std::optional<StoneModel> model(std::size_t kind) const override {
        if (tables_[kind]) return std::nullopt;
        return rest_->model(kind);
    }
    void set_model(std::size_t kind, const StoneModel& model) override {
        if (!tables_[kind]) rest_->set_model(kind, model);
    }
    Result<bool> draw_alone(std::size_t kind, const StoneFrame& frame,
                            const StoneModel& model) override {
        if (tables_[kind]) return Error{"a stone drawn from its tables has no models"};
        return rest_->draw_alone(kind, frame, model);
    }

    std::string describe() const override {
        std::string line = rest_->describe();
        for (const auto& table : tables_) {
            if (!table) continue;
            line += (line.empty() ? "" : "; ") + std::string("'") + table->database().stone().name +
                    "' from its tables, " + table->database().path().filename().string();
        }
        return line;
    }

  private:
    void select_rest(const std::vector<StoneFrame>& frames, const std::vector<std::size_t>& kinds) {
        std::size_t j = 0;
        for (std::size_t i = 0; i < frames.size(); ++i) {
            if (tables_[kinds[i]]) continue;
            rest_frames_[j] = frames[i];
            rest_kinds_[j] = kinds[i];
            ++j;
        }
    }

    std::unique_ptr<StoneMethod> rest_;
    std::vector<std::unique_ptr<TableMethod>> tables_;
    std::vector<std::vector<std::size_t>> stones_of_kind_;
    std::vector<Placement> placements_;  // each stone's
    std::vector<StoneFrame> rest_frames_;
    std::vector<std::size_t> rest_kinds_;
    std::vector<ViewHeading> headings_;
};

}  // namespace

Result<std::unique_ptr<StoneMethod>> with_kind_tables(std::unique_ptr<StoneMethod> rest,
                                                      const FrameSetup& setup,
                                                      const std::vector<const Stone*>& kinds,
                                                      const std::vector<std::size_t>& stone_kinds,
                                                      const std::vector<Placement>& placements) {
    std::vector<std::unique_ptr<TableMethod>> tables(kinds.size());
    std::vector<std::vector<std::size_t>> stones_of_kind(kinds.size());
    for (std::size_t i = 0; i < stone_kinds.size(); ++i)
        stones_of_kind[stone_kinds[i]].push_back(i);
    bool any = false;
    for (std::size_t k = 0; k < kinds.size() && k < setup.kind_tables.size(); ++k) {
        const std::shared_ptr<const Database>& database = setup.kind_tables[k];
        if (!database) continue;
        const std::string which =
            "the tables " + database->path().string() + " for the piece's '" + kinds[k]->name + "'";
        if (!same_stored_stone(database->stone(), *kinds[k])) {
            return Error{which +
                         " store another stone (built from another description, "
                         "material or width: gemtables build --width-mm)"};
        }
        if (database->camera().kind != CameraModel::Kind::orthographic) {
            return Error{which +
                         " were built for a perspective camera; a piece is drawn "
                         "orthographic"};
        }
        // Stored views stop at their lowest elevation; a piece turns its stones every way.
        if (database->params().grid.min_elevation_rad > -std::numbers::pi / 2.0 + 1e-9) {
            return Error{which +
                         " do not store every direction (gemtables build "
                         "--min-elevation -90)"};
        }
        TableOptions options = setup.table;
        const std::size_t per_stone = options.blend ? 2 : 1;
        options.gpu_views = per_stone * stones_of_kind[k].size() + 1;
        auto made = TableMethod::make(database, options);
        if (!made) return Error{made.error()};
        tables[k] = std::make_unique<TableMethod>(std::move(made).value());
        any = true;
    }
    if (!any) return rest;
    return std::unique_ptr<StoneMethod>(std::make_unique<PieceTables>(
        std::move(rest), std::move(tables), std::move(stones_of_kind), placements));
}

}  // namespace gem::gpu
