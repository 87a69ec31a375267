#include "app/scene_build.hpp"

#include <cstdio>
#include <string>
#include <utility>

#include "gpu/stone_method.hpp"
#include "service/log.hpp"

namespace gem::kiosk {

namespace {

void log_framing(const StoneScene& scene, glm::ivec2 picture_size) {
    const Framing& framing = scene.framing(picture_size);
    char line[160];
    std::snprintf(line, sizeof line, "framing: the girdle spans %.0f%% of the picture's height%s",
                  100.0 * framing.stone_share,
                  framing.ring_cut ? "; the ring does not fit whole at that size"
                                   : ", the whole ring in view");
    log_info(line);
}

}  // namespace

BuiltScene build_scene(const CatalogueStone& selected, const LookChoice& look,
                       const RenderChoice& render, const DesignTables& designs,
                       glm::ivec2 picture_size) {
    BuiltScene built;
    CatalogueStone stone = selected;
    RenderChoice from_tables = render;
    built.tables = designs.tables_for(stone);
    const bool piece = stone.placed != nullptr;
    if (!built.tables.empty() && !piece) {
        stone.opened = built.tables.front();
        from_tables.method = gpu::tables_method().name;
    }
    auto made = StoneScene::make(stone, look, from_tables,
                                 piece ? built.tables : DesignTables::KindTables{});
    if (!made && !built.tables.empty()) {
        log_error(made.error() + "; drawn without its tables");
        built.tables.clear();
        made = StoneScene::make(selected, look, render);
    }
    if (!made) {
        log_error(made.error());
        return built;
    }
    built.scene = std::move(made).value();
    StoneScene& scene = *built.scene;
    log_framing(scene, picture_size);
    if (auto models = scene.choose_stone_models(picture_size)) {
        for (const std::string& line : models.value()) log_info(line);
    } else {
        log_error(models.error() + "; the stones not measured keep the configured model");
    }
    const std::string settled = scene.renderer().method().describe();
    if (!settled.empty()) log_info(scene.renderer().method_name() + ": " + settled);
    if (const std::string& note = scene.renderer().sight_note(); !note.empty()) log_error(note);
    return built;
}

}  // namespace gem::kiosk
