// The pixel ray of engine/picture/camera.cpp's Camera::ray, per fragment, in the stone frame.
uniform vec3 u_cam_forward;
uniform vec3 u_cam_right;
uniform vec3 u_cam_up;
uniform vec2 u_cam_half;       // half the image's extent: mm (orthographic) or tangent units
uniform float u_cam_distance;  // eye distance (perspective); 0: orthographic
uniform float u_cam_start;     // orthographic rays start this far behind the centre
uniform vec2 u_cam_shift;      // where the stone's centre appears, ndc (Camera::shift)

// The image-plane position of ndc (-1..1 across the viewport, y up), in u_cam_half's units.
vec2 image_plane(vec2 ndc) { return (ndc - u_cam_shift) * u_cam_half; }

void camera_ray(vec2 ndc, out vec3 origin, out vec3 direction) {
    vec2 s = image_plane(ndc);
    if (u_cam_distance > 0.0) {
        origin = -u_cam_forward * u_cam_distance;
        direction = normalize(u_cam_forward + s.x * u_cam_right + s.y * u_cam_up);
    } else {
        origin = -u_cam_forward * u_cam_start + s.x * u_cam_right + s.y * u_cam_up;
        direction = u_cam_forward;
    }
}

uniform vec2 u_viewport_px;     // the picture's size in pixels (camera.width(), height())

// The ndc of this fragment's pixel centre, for fragment shaders drawn over the picture.
vec2 fragment_ndc(vec4 frag_coord) { return frag_coord.xy / u_viewport_px * 2.0 - 1.0; }
