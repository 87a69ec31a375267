#include "picture/camera.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace gem {

namespace {

constexpr double kDegree = 3.14159265358979323846 / 180.0;

}  // namespace

glm::dvec3 view_forward(const CameraSettings& s) {
    const double az = s.azimuth_deg * kDegree;
    const double el = s.elevation_deg * kDegree;
    return -glm::dvec3(std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az));
}

Camera Camera::in_frame(const glm::dmat3& rotation, const glm::dvec3& position) const {
    Camera c = *this;
    const glm::dmat3 back = glm::transpose(rotation);
    c.forward_ = back * forward_;
    c.right_ = back * right_;
    c.up_ = back * up_;
    if (!orthographic()) return c;
    // A ray at image offset s: −f·start + s·(r, u) here is −f·(start + a) + (s − (b, c))·(r, u)
    // in the other frame, where (a, b, c) is `position` along (f, r, u).
    c.ray_start_ = ray_start_ + glm::dot(position, forward_);
    c.shift_ += glm::dvec2(glm::dot(position, right_) / (0.5 * width_ * pixel_size_),
                           glm::dot(position, up_) / (0.5 * height_ * pixel_size_));
    return c;
}

Result<Camera> Camera::make(const CameraSettings& s, double bounding_radius_mm, int width,
                            int height) {
    if (width <= 0 || height <= 0) return Error{"camera: the image size must be positive"};
    if (!(s.zoom > 0.0)) return Error{"camera.zoom: must be positive"};
    if (!(bounding_radius_mm > 0.0)) return Error{"camera: the stone has no extent"};
    if (s.perspective_distance_mm != 0.0 && !(s.perspective_distance_mm > bounding_radius_mm)) {
        return Error{"camera.perspective: the eye (" + std::to_string(s.perspective_distance_mm) +
                     " mm) must be outside the stone's bounding sphere (radius " +
                     std::to_string(bounding_radius_mm) + " mm)"};
    }
    Camera cam;
    const double az = s.azimuth_deg * kDegree;
    cam.forward_ = view_forward(s);
    // Right stays horizontal and depends on azimuth only, so the basis has no singularity at
    // the poles: looking straight down, the image's up is the far side of the stone.
    const glm::dvec3 right0(std::cos(az), 0.0, -std::sin(az));
    const glm::dvec3 up0 = glm::cross(right0, cam.forward_);
    const double roll = s.roll_deg * kDegree;
    cam.right_ = std::cos(roll) * right0 + std::sin(roll) * up0;
    cam.up_ = -std::sin(roll) * right0 + std::cos(roll) * up0;
    cam.width_ = width;
    cam.height_ = height;
    cam.shift_ = s.shift;
    const double shorter = static_cast<double>(std::min(width, height));
    if (s.perspective_distance_mm > 0.0) {
        cam.distance_ = s.perspective_distance_mm;
        // The cone from the eye tangent to the bounding sphere has half-angle asin(r / D).
        const double half_angle = std::asin(bounding_radius_mm / cam.distance_);
        cam.pixel_size_ = 2.0 * std::tan(half_angle) / (s.zoom * shorter);
    } else {
        cam.ray_start_ = 2.0 * bounding_radius_mm;
        cam.pixel_size_ = 2.0 * bounding_radius_mm / (s.zoom * shorter);
    }
    return cam;
}

Ray Camera::ray(double px, double py) const {
    const double sx = (px - 0.5 * width_ * (1.0 + shift_.x)) * pixel_size_;
    const double sy = (0.5 * height_ * (1.0 - shift_.y) - py) * pixel_size_;
    Ray r;
    if (distance_ > 0.0) {
        r.origin = -forward_ * distance_;
        r.direction = glm::normalize(forward_ + sx * right_ + sy * up_);
    } else {
        r.origin = -forward_ * ray_start_ + sx * right_ + sy * up_;
        r.direction = forward_;
    }
    return r;
}

}  // namespace gem
