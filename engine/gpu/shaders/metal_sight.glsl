// What the metal sees of its own piece, in a still view's frames (ring_renderer.hpp): the split
// sum (metal.glsl) assumes the metal sees only the environment. Where it sees its piece, one
// reflected ray, drawn from GGX as the reference draws it (Walter eq. 35-38) and followed
// through the piece's triangles (piece_path.glsl), corrects it by what it meets less what the
// environment would have shown there: a control variate, so a ray that escapes adds nothing
// and no noise, and the mean over the still frames is the metal seeing its piece as the
// reference's does (cpu/piece_tracer.cpp). Compiled in with SEES_PIECE. The lights' lobes
// the split sum reflects are left as they are where the first ray meets the piece (the
// reference's would be blocked there): taking them off too made single frames dark where a
// lobe is narrow and bright, specks on a white look's metal after 20 frames, for 0.04 ΔE00 or
// less on the shipped pieces' close views.
// Each pixel traces its own ray, in its tile's turn (sight_traced()). One ray a 4×4 block, its
// correction spread over the block's surface by depth, put the still pictures further from the
// reference (the halo 4.41 against 3.32 ΔE00 after 16 frames) and blurred a polished metal's
// reflections of its stones, for a third of the time on llvmpipe, not a sixteenth: the cost
// follows the slowest ray of a block of lanes, not the count of rays.

#ifdef SEES_PIECE
// The correction of the split sum by what one reflected ray meets of the piece (see above),
// weighed for the frames its tile does not trace.
vec3 piece_correction(vec3 p, vec3 n, vec3 face, vec3 v) {
    if (!sight_traced()) return vec3(0.0);
    vec3 l, weight;
    if (!sample_reflection(n, v, frame_random(), l, weight)) return vec3(0.0);
    vec3 o = p + face * u_ray_offset_mm;
    bool met;
    vec3 seen = path_radiance(o, l, 1.0, vec3(0.0), met);
    // A ray that leaves the piece at once sees what the split sum counted: nothing to add;
    // one that meets it sees the piece instead of the environment.
    return met ? float(kSightFrames) * weight *
                     (seen - textureLod(u_environment_sharp, l, 0.0).rgb)
               : vec3(0.0);
}
#endif
