#pragma once
// The camera orbits the stone's centre. Its view direction is given in the stone frame by
// azimuth and elevation; roll turns the image about the view axis and zoom scales it.
// Orthographic by default (docs/design.md, "Contracts": a stone seen from a shop counter is
// almost orthographic), or perspective from a fixed distance.

#include <vector>

#include "trace/ray_list.hpp"
#include "util/result.hpp"

namespace gem {

struct CameraSettings {
    // Where the camera sits, seen from the stone: azimuth about +y, measured from +z toward
    // +x; elevation above the girdle plane (90° = straight above the table, looking down -y).
    double azimuth_deg = 0.0;
    double elevation_deg = 90.0;
    // Turns the camera counter-clockwise about its view axis, so the picture turns clockwise.
    double roll_deg = 0.0;
    double zoom = 1.0;  // 1: the stone's bounding sphere just fits the shorter image side
    double perspective_distance_mm = 0.0;  // 0: orthographic; else the eye's distance
    // Where the stone's centre appears, in normalised image coordinates (-1..1 across the
    // picture, x right, y up): a framing choice that moves the picture, not the view.
    glm::dvec2 shift{0.0};
};

// The direction the camera looks along (stone frame, unit): from its azimuth and elevation
// alone, what Camera::forward() is without making the camera.
glm::dvec3 view_forward(const CameraSettings& settings);

class Camera {
  public:
    // `bounding_radius_mm`: radius of a sphere about the stone-frame origin holding the stone.
    // Errors: zoom not positive, a perspective eye inside that sphere, an empty image.
    static Result<Camera> make(const CameraSettings& settings, double bounding_radius_mm, int width,
                               int height);

    // The same camera, its rays written in another frame: `rotation` and `position` take that
    // frame's points into this camera's frame (a stone placed in a piece). The picture is the
    // same; the rays start elsewhere and the stone's centre appears shifted. Orthographic
    // cameras only: a perspective camera comes back with its basis turned and its eye where it
    // was, which is right only when `position` is zero (the frame renderer refuses a piece
    // seen in perspective).
    Camera in_frame(const glm::dmat3& rotation, const glm::dvec3& position) const;

    // The ray through image position (px, py) in pixels: (0, 0) the top-left corner of the
    // image, (width, height) the bottom-right one; pixel (i, j) covers [i, i+1) × [j, j+1).
    Ray ray(double px, double py) const;

    // Unit direction the camera looks along, and the image's right and up directions
    // (stone frame); for an orthographic camera every pixel ray has direction forward().
    const glm::dvec3& forward() const { return forward_; }
    const glm::dvec3& right() const { return right_; }
    const glm::dvec3& up() const { return up_; }
    bool orthographic() const { return distance_ <= 0.0; }
    double distance() const { return distance_; }    // eye distance; 0 when orthographic
    double ray_start() const { return ray_start_; }  // orthographic rays start this far back
    // Image-plane extent of one pixel: mm (orthographic) or tangent units at unit distance.
    double pixel_size() const { return pixel_size_; }
    int width() const { return width_; }
    int height() const { return height_; }
    const glm::dvec2& shift() const { return shift_; }

  private:
    glm::dvec3 forward_{0.0, -1.0, 0.0};
    glm::dvec3 right_{1.0, 0.0, 0.0};
    glm::dvec3 up_{0.0, 0.0, -1.0};
    double distance_ = 0.0;   // eye distance, 0 for orthographic
    double ray_start_ = 0.0;  // orthographic rays start this far back from the centre
    double pixel_size_ = 0.0;
    glm::dvec2 shift_{0.0};
    int width_ = 0;
    int height_ = 0;
};

}  // namespace gem
