// Database round trip: ray-lists written and read back equal the input within the quantisation
// bounds, field by field; metadata exactly; the same inputs give the same bytes on any number
// of threads; a failed write leaves no file behind.

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cmath>

#include "gemdb/quantise.hpp"
#include "gemdb/reader.hpp"
#include "gemdb/writer.hpp"
#include "tables_test_support.hpp"

namespace gem {
namespace {

using namespace tables_test;

double angle_between(const glm::dvec3& a, const glm::dvec3& b) {
    return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

// |decoded − exact| allowed for a half: 2^-11 relative (normal), 2^-25 absolute (subnormal),
// plus the double → float step (2^-24 relative) twice over for the float the decoder returns.
double half_tolerance(double exact) {
    return std::max(kHalfMaxRelativeError * std::abs(exact), kHalfMaxSubnormalError) +
           std::ldexp(std::abs(exact), -23) + 1e-30;
}

void expect_ray(const DecodedView& view, std::size_t r, const TracedRay& exact,
                const PositionBox& box, const glm::dvec3* dn) {
    // float storage of the decoded unit vector adds < 1e-7 rad.
    EXPECT_LE(angle_between(glm::dvec3(view.direction[r]), exact.direction),
              kOctahedralMaxAngle + 1e-7);
    EXPECT_LE(std::abs(view.weight[r] - exact.weight), half_tolerance(exact.weight));
    EXPECT_LE(std::abs(view.path_mm[r] - exact.path_mm), half_tolerance(exact.path_mm));
    const glm::dvec3 bound = box.max_error() + 4e-7;  // + float rounding of a ≤ 3 mm coordinate
    const glm::dvec3 error = glm::abs(glm::dvec3(view.position[r]) - exact.origin);
    EXPECT_LE(error.x, bound.x);
    EXPECT_LE(error.y, bound.y);
    EXPECT_LE(error.z, bound.z);
    EXPECT_EQ(view.bounces[r], exact.bounces);
    EXPECT_EQ(view.facet[r], exact.facet);
    if (dn != nullptr) {
        for (int a = 0; a < 3; ++a)
            EXPECT_LE(std::abs(view.dir_dn[r][a] - (*dn)[a]), half_tolerance((*dn)[a]));
    }
}

void expect_round_trip(bool dispersion) {
    const SmallDatabase input = small_database(dispersion);
    const auto path = artifact_dir("round_trip") / (dispersion ? "fire.gemdb" : "plain.gemdb");
    auto written = write_small(path, input);
    ASSERT_TRUE(written.ok()) << written.error();
    auto opened = Database::open(path);
    ASSERT_TRUE(opened.ok()) << opened.error();
    const Database& db = opened.value();

    // Metadata comes back exactly.
    const Stone& s = db.stone();
    EXPECT_EQ(s.name, input.stone.name);
    EXPECT_EQ(s.vertices, input.stone.vertices);
    ASSERT_EQ(s.facets.size(), input.stone.facets.size());
    for (std::size_t f = 0; f < s.facets.size(); ++f) {
        EXPECT_EQ(s.facets[f].plane.n, input.stone.facets[f].plane.n);
        EXPECT_EQ(s.facets[f].plane.d, input.stone.facets[f].plane.d);
        EXPECT_EQ(s.facets[f].loop, input.stone.facets[f].loop);
        EXPECT_EQ(s.facets[f].kind, input.stone.facets[f].kind);
        EXPECT_EQ(s.facets[f].name, input.stone.facets[f].name);
    }
    ASSERT_EQ(s.triangles.size(), input.stone.triangles.size());
    EXPECT_EQ(s.triangles[5].v, input.stone.triangles[5].v);
    EXPECT_EQ(s.triangles[5].facet, input.stone.triangles[5].facet);
    EXPECT_EQ(s.symmetry, input.stone.symmetry);
    EXPECT_EQ(db.material().name, "test sapphire");
    EXPECT_EQ(db.material().dispersion.kind, Dispersion::Kind::cauchy);
    EXPECT_EQ(db.material().dispersion.coef, input.stone.material.dispersion.coef);
    EXPECT_EQ(db.material().body_colour, input.stone.material.body_colour);
    EXPECT_EQ(db.material().absorption_per_mm, input.stone.material.absorption_per_mm);
    EXPECT_EQ(db.camera().kind, CameraModel::Kind::perspective);
    EXPECT_EQ(db.camera().distance_mm, 40.0);
    EXPECT_EQ(db.camera().field_mm, 7.0);
    EXPECT_EQ(db.params().levels, input.params.levels);
    EXPECT_EQ(db.params().grid.spacing_rad, 0.45);
    EXPECT_EQ(db.params().grid.min_elevation_rad, -0.3);
    EXPECT_EQ(db.params().weight_threshold, 1e-4);
    EXPECT_EQ(db.params().dispersion, dispersion);
    EXPECT_EQ(db.grid().directions(), input.grid.directions());
    EXPECT_EQ(db.grid().group(), input.grid.group());
    // The position box is the stone's bounding box (6 × 3 × 4 mm).
    EXPECT_EQ(db.position_box().min, glm::dvec3(-3.0, -1.5, -2.0));
    EXPECT_EQ(db.position_box().max, glm::dvec3(3.0, 1.5, 2.0));

    std::uint64_t rays = 0;
    for (std::uint32_t v = 0; v < db.view_count(); ++v) {
        for (std::uint32_t l = 0; l < db.level_count(); ++l) {
            const std::uint32_t side = input.params.levels[l];
            const auto lists = random_lists(chunk_seed(v, l), side);
            const auto dn = random_derivatives(lists, chunk_seed(v, l) + 1);
            auto decoded = db.decode(v, l);
            ASSERT_TRUE(decoded.ok()) << decoded.error();
            const DecodedView& view = decoded.value();
            ASSERT_EQ(view.side, side);
            ASSERT_EQ(view.dir_dn.size(), dispersion ? view.direction.size() : 0u);
            std::size_t dn_index = 0;
            for (std::size_t p = 0; p < lists.size(); ++p) {
                const RayList& list = lists[p];
                if (!list.hit) {
                    EXPECT_EQ(view.ray_count[p], 0);
                    continue;
                }
                std::size_t r = view.ray_offset[p];
                const glm::dvec3 zero(0.0);
                expect_ray(view, r++, list.reflected, db.position_box(),
                           dispersion ? &zero : nullptr);
                double dropped = 0.0;
                for (const TracedRay& exit : list.exits) {
                    const glm::dvec3& d = dn[dn_index++];
                    if (exit.weight < 1e-4) {
                        dropped += exit.weight;
                        continue;
                    }
                    expect_ray(view, r++, exit, db.position_box(), dispersion ? &d : nullptr);
                }
                EXPECT_EQ(r - view.ray_offset[p], view.ray_count[p]);
                const double truncated = list.truncated_weight + dropped;
                EXPECT_LE(std::abs(view.truncated_weight[p] - truncated),
                          half_tolerance(truncated));
                rays += view.ray_count[p];
            }
            EXPECT_EQ(db.payload(v, l).rays, view.direction.size());
        }
    }
    EXPECT_EQ(rays, written.value().rays);
    EXPECT_GT(rays, 1000u);
}

TEST(TablesDatabase, RoundTripWithinQuantisationBounds) {
    expect_round_trip(false);
}

TEST(TablesDatabase, RoundTripWithDispersionDerivatives) {
    expect_round_trip(true);
}

TEST(TablesDatabase, SameInputsSameBytesOnAnyThreadCount) {
    const SmallDatabase input = small_database(true);
    const auto dir = artifact_dir("determinism");
    ASSERT_TRUE(write_small(dir / "a.gemdb", input, 1).ok());
    ASSERT_TRUE(write_small(dir / "b.gemdb", input, 3).ok());
    const auto a = read_bytes(dir / "a.gemdb");
    const auto b = read_bytes(dir / "b.gemdb");
    ASSERT_GT(a.size(), 1000u);
    EXPECT_TRUE(a == b) << "two writes of the same inputs differ";
}

TEST(TablesDatabase, MissedPixelsCostAlmostNothing) {
    SmallDatabase input = small_database(false);
    input.params.levels = {64};
    const auto path = artifact_dir("empty") / "empty.gemdb";
    auto written =
        write_database(path, input.stone, input.camera, input.params, input.grid,
                       [](std::uint32_t, std::uint32_t) { return std::vector<RayList>(64 * 64); });
    ASSERT_TRUE(written.ok()) << written.error();
    auto db = Database::open(path);
    ASSERT_TRUE(db.ok()) << db.error();
    // 8 count bytes and a 512-byte coverage mask per view, compressed to a few dozen bytes.
    EXPECT_EQ(db.value().payload(0, 0).raw_bytes, 8u + 64u * 64u / 8u);
    EXPECT_LT(db.value().payload(0, 0).compressed_bytes, 64u);
    auto view = db.value().decode(0, 0);
    ASSERT_TRUE(view.ok()) << view.error();
    EXPECT_TRUE(view.value().direction.empty());
}

TEST(TablesDatabase, FailedWriteLeavesNoFile) {
    const SmallDatabase input = small_database(false);
    const auto dir = artifact_dir("atomic");
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    // A missing directory.
    auto missing = write_small(dir / "no" / "such" / "x.gemdb", input);
    ASSERT_FALSE(missing.ok());
    EXPECT_NE(missing.error().find((dir / "no" / "such" / "x.gemdb").string()), std::string::npos);
    // A place nobody may create files in, root included.
    auto proc = write_small("/proc/gemkiosk-test.gemdb", input);
    ASSERT_FALSE(proc.ok());
    EXPECT_NE(proc.error().find("/proc/gemkiosk-test.gemdb"), std::string::npos);
    // A read-only directory (root ignores the mode, so only checked for other users).
    if (::geteuid() != 0) {
        const auto locked = dir / "locked";
        std::filesystem::create_directories(locked);
        ::chmod(locked.c_str(), 0555);
        auto denied = write_small(locked / "x.gemdb", input);
        ::chmod(locked.c_str(), 0755);
        ASSERT_FALSE(denied.ok());
        EXPECT_TRUE(std::filesystem::is_empty(locked));
    }
    // A trace that fails half way: the old file stays as it was, no temporary is left.
    const auto path = dir / "kept.gemdb";
    ASSERT_TRUE(write_small(path, input).ok());
    const auto before = read_bytes(path);
    auto failed = write_database(path, input.stone, input.camera, input.params, input.grid,
                                 [&](std::uint32_t view, std::uint32_t level) {
                                     if (view == 2) throw std::runtime_error("tracer exploded");
                                     return random_lists(1, input.params.levels[level]);
                                 });
    ASSERT_FALSE(failed.ok());
    EXPECT_NE(failed.error().find(path.string()), std::string::npos);
    EXPECT_NE(failed.error().find("tracer exploded"), std::string::npos);
    EXPECT_EQ(read_bytes(path), before);
    std::size_t files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(dir))
        files += entry.is_regular_file();
    EXPECT_EQ(files, 1u) << "a temporary file was left behind";
    // A callback returning the wrong number of ray-lists is an error naming view and level.
    auto short_list =
        write_database(path, input.stone, input.camera, input.params, input.grid,
                       [](std::uint32_t, std::uint32_t) { return std::vector<RayList>(3); });
    ASSERT_FALSE(short_list.ok());
    EXPECT_NE(short_list.error().find("view 0 level 0"), std::string::npos);
}

TEST(TablesDatabase, WriterRefusesARayNamingAMissingFacet) {
    const SmallDatabase input = small_database(false);
    const auto dir = artifact_dir("facets");
    const auto path = dir / "bad-facet.gemdb";
    std::filesystem::remove(path);
    const std::size_t facets = input.stone.facets.size();
    for (const bool exit_ray : {false, true}) {
        auto written = write_database(
            path, input.stone, input.camera, input.params, input.grid,
            [&](std::uint32_t view, std::uint32_t level) {
                std::vector<RayList> lists =
                    random_lists(chunk_seed(view, level), input.params.levels[level]);
                if (view != 1 || level != 1) return lists;
                for (RayList& list : lists) {
                    if (!list.hit) continue;
                    if (!exit_ray) {
                        list.reflected.facet = static_cast<std::uint32_t>(facets);
                        break;
                    }
                    if (list.exits.empty()) continue;
                    list.exits.back().weight = 0.5;  // kept, not dropped by the threshold
                    list.exits.back().facet = static_cast<std::uint32_t>(facets);
                    break;
                }
                return lists;
            });
        ASSERT_FALSE(written.ok()) << (exit_ray ? "exit ray" : "reflection");
        EXPECT_NE(written.error().find(path.string()), std::string::npos) << written.error();
        EXPECT_NE(written.error().find("view 1 level 1"), std::string::npos) << written.error();
        EXPECT_NE(written.error().find("a ray names facet 6 of a stone with 6"), std::string::npos)
            << written.error();
        EXPECT_FALSE(std::filesystem::exists(path));
    }
}

TEST(TablesDatabase, WriterRefusesCoefficientsThatDoNotFitTheDispersionKind) {
    const auto dir = artifact_dir("coefficients");
    const auto path = dir / "material.gemdb";
    using K = Dispersion::Kind;
    const std::vector<std::pair<K, std::vector<double>>> bad = {
        {K::constant, {}},  {K::cauchy, {}},       {K::cauchy, {1.7}},
        {K::sellmeier, {}}, {K::sellmeier, {1.4}}, {K::sellmeier, {0.7, 0.06, 0.4}},
    };
    for (const auto& [kind, coef] : bad) {
        SmallDatabase input = small_database(false);
        input.stone.material.dispersion.kind = kind;
        input.stone.material.dispersion.coef = coef;
        std::filesystem::remove(path);
        auto written = write_small(path, input);
        ASSERT_FALSE(written.ok()) << "kind " << int(kind) << " with " << coef.size();
        EXPECT_NE(written.error().find(path.string()), std::string::npos) << written.error();
        EXPECT_NE(written.error().find(std::to_string(coef.size()) +
                                       " coefficients, which do not fit its kind"),
                  std::string::npos)
            << written.error();
        EXPECT_FALSE(std::filesystem::exists(path));
    }
    const std::vector<std::pair<K, std::vector<double>>> good = {
        {K::constant, {2.417}},
        {K::cauchy, {1.7, 0.006}},
        {K::cauchy, {1.7, 0.006, 0.0001}},
        {K::sellmeier, {0.7, 0.06}},
        {K::sellmeier, {0.7, 0.06, 0.4, 0.1}},
    };
    for (const auto& [kind, coef] : good) {
        SmallDatabase input = small_database(false);
        input.stone.material.dispersion.kind = kind;
        input.stone.material.dispersion.coef = coef;
        auto written = write_small(path, input);
        ASSERT_TRUE(written.ok()) << written.error();
        auto db = Database::open(path);
        ASSERT_TRUE(db.ok()) << db.error();
        EXPECT_EQ(db.value().stone().material.dispersion.coef, coef);
    }
}

}  // namespace
}  // namespace gem
