#pragma once
// The scene of the stone selected, made as the kiosk shows it: a design whose tables are
// built and checked is drawn from them, as are a piece's stones whose tables are
// (builds/design_tables.hpp); tables that turn out not to serve it (another build of it) are
// left aside and the stone drawn as the render choice asks. The scene is framed and its
// stones modelled for the picture's size, each decision said in one log line.

#include <memory>

#include <glm/glm.hpp>

#include "builds/design_tables.hpp"
#include "catalogue/catalogue.hpp"
#include "stage/stone_scene.hpp"

namespace gem::kiosk {

struct BuiltScene {
    std::unique_ptr<StoneScene> scene;  // null: it could not be made (said in the log)
    DesignTables::KindTables tables;    // the tables it is drawn from
};

BuiltScene build_scene(const CatalogueStone& stone, const LookChoice& look,
                       const RenderChoice& render, const DesignTables& designs,
                       glm::ivec2 picture_size);

}  // namespace gem::kiosk
