// Camera: ray directions, the pole, roll and framing. Expected values are worked out by hand
// from the stated conventions (azimuth from +z toward +x, elevation above the girdle plane).
#include <cmath>

#include <gtest/gtest.h>
#include <glm/gtx/rotate_vector.hpp>

#include "picture/camera.hpp"

namespace gem {
namespace {

constexpr double kPi = 3.14159265358979323846;

Camera make_camera(const CameraSettings& s, double radius = 5.0, int w = 64, int h = 64) {
    Result<Camera> cam = Camera::make(s, radius, w, h);
    EXPECT_TRUE(cam.ok()) << (cam.ok() ? "" : cam.error());
    return std::move(cam).value();
}

void expect_near(const glm::dvec3& a, const glm::dvec3& b, double tol = 1e-12) {
    EXPECT_NEAR(a.x, b.x, tol);
    EXPECT_NEAR(a.y, b.y, tol);
    EXPECT_NEAR(a.z, b.z, tol);
}

// Distance from point p to the line through the ray.
double distance_to_ray_line(const Ray& r, const glm::dvec3& p) {
    const glm::dvec3 v = p - r.origin;
    return glm::length(v - glm::dot(v, r.direction) * r.direction);
}

TEST(RenderCamera, OrthographicRaysAreParallelToTheViewDirection) {
    struct Case {
        double azimuth, elevation;
        glm::dvec3 expected;  // by hand: minus the unit vector toward the eye
    };
    const double c30 = std::sqrt(3.0) / 2.0;
    const double s45 = std::sqrt(0.5);
    const Case cases[] = {
        {0.0, 0.0, {0.0, 0.0, -1.0}},   {90.0, 0.0, {-1.0, 0.0, 0.0}},
        {180.0, 0.0, {0.0, 0.0, 1.0}},  {45.0, 30.0, {-c30 * s45, -0.5, -c30 * s45}},
        {0.0, -60.0, {0.0, c30, -0.5}},
    };
    for (const Case& c : cases) {
        const Camera cam = make_camera({.azimuth_deg = c.azimuth, .elevation_deg = c.elevation});
        for (double px : {0.0, 10.5, 63.9}) {
            for (double py : {0.0, 31.0, 64.0}) {
                expect_near(cam.ray(px, py).direction, c.expected);
            }
        }
    }
}

TEST(RenderCamera, ElevationNinetyLooksStraightDown) {
    for (double azimuth : {0.0, 37.0, 200.0}) {
        const Camera cam = make_camera({.azimuth_deg = azimuth, .elevation_deg = 90.0});
        const Ray r = cam.ray(20.0, 40.0);
        expect_near(r.direction, {0.0, -1.0, 0.0});
        EXPECT_GT(r.origin.y, 5.0);  // starts above the stone's bounding sphere
    }
}

TEST(RenderCamera, ImageAxesFollowTheConvention) {
    // Seen from +z (azimuth 0, elevation 0): right is +x and up is +y.
    const Camera cam = make_camera({.azimuth_deg = 0.0, .elevation_deg = 0.0});
    const Ray centre = cam.ray(32.0, 32.0);
    const Ray right = cam.ray(48.0, 32.0);
    const Ray top = cam.ray(32.0, 16.0);
    EXPECT_GT(right.origin.x - centre.origin.x, 0.0);
    EXPECT_NEAR(right.origin.y, centre.origin.y, 1e-12);
    EXPECT_GT(top.origin.y - centre.origin.y, 0.0);
    EXPECT_NEAR(top.origin.x, centre.origin.x, 1e-12);
}

TEST(RenderCamera, RollRotatesTheImageAboutTheViewAxis) {
    const CameraSettings base{.azimuth_deg = 25.0, .elevation_deg = 50.0};
    const Camera cam0 = make_camera(base);
    for (double roll : {30.0, -75.0, 180.0}) {
        CameraSettings rolled = base;
        rolled.roll_deg = roll;
        const Camera cam = make_camera(rolled);
        // A positive roll turns the camera counter-clockwise as seen from the eye, i.e. about
        // the axis pointing back at the eye; glm::rotate is Rodrigues' formula, independent of
        // the camera's basis construction.
        const glm::dvec3 axis = -cam0.forward();
        for (const auto& [px, py] : {std::pair{10.0, 20.0}, std::pair{60.0, 5.0}}) {
            const glm::dvec3 o0 = cam0.ray(px, py).origin;
            const glm::dvec3 expected = glm::rotate(o0, roll * kPi / 180.0, axis);
            expect_near(cam.ray(px, py).origin, expected, 1e-9);
            expect_near(cam.ray(px, py).direction, cam0.forward());
        }
    }
}

TEST(RenderCamera, BoundingSphereJustFitsTheShorterSide) {
    const double radius = 4.0;
    const glm::dvec3 centre(0.0);
    // Orthographic: the ray through the middle of the left edge grazes the sphere.
    const Camera ortho = make_camera({.azimuth_deg = 10.0, .elevation_deg = 70.0}, radius, 80, 80);
    EXPECT_NEAR(distance_to_ray_line(ortho.ray(0.0, 40.0), centre), radius, 1e-9);
    EXPECT_NEAR(distance_to_ray_line(ortho.ray(40.0, 0.0), centre), radius, 1e-9);
    EXPECT_NEAR(distance_to_ray_line(ortho.ray(40.0, 40.0), centre), 0.0, 1e-9);
    // A wide image: the height is the shorter side and fits; zoom 2 halves the view.
    const Camera wide = make_camera({.elevation_deg = 90.0, .zoom = 2.0}, radius, 120, 60);
    EXPECT_NEAR(distance_to_ray_line(wide.ray(60.0, 0.0), centre), radius / 2.0, 1e-9);
    // Perspective from 20 mm: the edge ray is tangent to the sphere.
    const Camera persp =
        make_camera({.azimuth_deg = 0.0, .elevation_deg = 30.0, .perspective_distance_mm = 20.0},
                    radius, 50, 50);
    EXPECT_NEAR(distance_to_ray_line(persp.ray(0.0, 25.0), centre), radius, 1e-9);
    EXPECT_NEAR(glm::length(persp.ray(3.0, 7.0).origin), 20.0, 1e-9);
}

TEST(RenderCamera, RejectsBadSettings) {
    EXPECT_FALSE(Camera::make({.zoom = 0.0}, 1.0, 8, 8).ok());
    EXPECT_FALSE(Camera::make({.perspective_distance_mm = 0.5}, 1.0, 8, 8).ok());
    EXPECT_FALSE(Camera::make({}, 1.0, 0, 8).ok());
}

TEST(RenderCamera, AShiftMovesTheStonesCentreToItsPlaceInThePicture) {
    // 64 × 32, shift (0.5, -0.25): the centre is seen at pixel (32 + 16, 16 + 4) for both
    // kinds of camera (y down in pixels, up in ndc).
    for (double distance : {0.0, 40.0}) {
        CameraSettings s;
        s.elevation_deg = 35.0;
        s.perspective_distance_mm = distance;
        s.shift = {0.5, -0.25};
        const Camera c = make_camera(s, 5.0, 64, 32);
        EXPECT_LT(distance_to_ray_line(c.ray(48.0, 20.0), glm::dvec3(0.0)), 1e-12) << distance;
        EXPECT_GT(distance_to_ray_line(c.ray(32.0, 16.0), glm::dvec3(0.0)), 0.5) << distance;
        // The pixel size is the shift's alone to keep: a shift is not a zoom.
        s.shift = {0.0, 0.0};
        EXPECT_EQ(make_camera(s, 5.0, 64, 32).pixel_size(), c.pixel_size());
    }
}

TEST(RenderCamera, TheViewDirectionWithoutACameraIsTheCamerasOwn) {
    // By hand: straight above looks down −y; from azimuth 90° on the horizon (the eye on +x)
    // it looks along −x; from azimuth 0° at 45° elevation, down and toward −z.
    CameraSettings s;
    EXPECT_NEAR(glm::length(view_forward(s) - glm::dvec3(0.0, -1.0, 0.0)), 0.0, 1e-12);
    s.azimuth_deg = 90.0;
    s.elevation_deg = 0.0;
    EXPECT_NEAR(glm::length(view_forward(s) - glm::dvec3(-1.0, 0.0, 0.0)), 0.0, 1e-12);
    s.azimuth_deg = 0.0;
    s.elevation_deg = 45.0;
    const double h = std::sqrt(0.5);
    EXPECT_NEAR(glm::length(view_forward(s) - glm::dvec3(0.0, -h, -h)), 0.0, 1e-12);
    // Roll, zoom and shift do not turn it.
    s.roll_deg = 30.0;
    s.zoom = 2.0;
    s.shift = {0.3, -0.2};
    EXPECT_NEAR(glm::length(view_forward(s) - Camera::make(s, 1.0, 64, 48).value().forward()), 0.0,
                1e-12);
}

}  // namespace
}  // namespace gem
