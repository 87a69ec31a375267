// What a stone in a piece sees of its setting, in a still view's frames (trace_method.hpp):
// the stone's exits read a virtual cube of its group (piece/sight_groups.hpp), which holds the
// environment and the metal as the split sum shades it, seen by direction from one point, and
// no stones. The exact reference follows each exit into the piece (cpu/piece_tracer.cpp):
// the claw beside the exit point, the neighbouring stones, the metal's own reflections. So one
// of the pixel's exits (its first reflection among them) is chosen, each with a chance in
// proportion to its weight times what the cube and the lights showed it plus the environment's
// mean (a weighted reservoir of one, Chao 1982: the exits come one at a time, and none is
// kept), followed through the piece (piece_path.glsl), and what it meets less what the cube
// and the lights gave it is added, weighed by the sum of the chances' sizes over the chosen
// one's: a control variate, whose mean over the still frames is every exit seeing the piece,
// whatever the chances. An exit the cube showed right adds nothing and no noise; one that
// showed a bright light the piece blocks adds most, so it is chosen most often (by weight
// alone, the halo's small stones were 6.0 ΔE00 from the exact piece after 17 frames and 4.4
// after 65; by weight and what was shown, 5.4 and 4.1: ctest -R GpuPiece -V). Fire stays in
// the cube's part: the chosen exit is seen along its own direction, not the ones first-order
// fire moves each channel's lookup to, and where each channel is traced at its own wavelength
// (FIRE_EXACT) the middle one's exits stand for all three. Each tile traces in its turn
// (sight_traced()), as the metal's do. Compiled in with SEES_PIECE; follows shading.glsl and
// piece_path.glsl. The stone's own frame, but for the path, in the piece's (u_frame_rotation,
// u_frame_origin).

#ifdef SEES_PIECE
bool g_sight_on = false;     // this pixel traces in this frame
vec3 g_channel_mix = vec3(1.0);  // FIRE_EXACT: what a trace's exits add to the channels
float g_sight_total = 0.0;   // the candidates' chances' sizes so far
float g_sight_chosen = 0.0;  // ... and the chosen one's
vec3 g_sight_p;
vec3 g_sight_d;
vec3 g_sight_n;
vec3 g_sight_weight;
float g_sight_k;
vec3 g_sight_env;     // what the cube showed it
vec3 g_sight_lights;  // ... and the lights, which the chosen exit need not be shaded for again

// The environment's mean radiance (its channels' mean): what an exit sees where its cube showed
// it dark, for the chance of following it (and a little more: a black environment's exits may
// still meet lit metal).
uniform float u_environment_mean;
const float kLeastShown = 1e-3;

// Once per entry traced (a multisampled pixel may trace one per facet its samples show).
void start_sight() {
    g_sight_total = 0.0;
    g_sight_chosen = 0.0;
    g_sight_on = sight_traced();
    if (g_sight_on) seed_random();
}

void sight_candidate(vec3 p, vec3 d, vec3 n, vec3 weight, float k, vec3 env, vec3 lights) {
    if (!g_sight_on) return;
    vec3 w = g_channel_mix * weight;
    float shown = dot(env + lights, vec3(1.0 / 3.0)) + u_environment_mean + kLeastShown;
    float size = (abs(w.r) + abs(w.g) + abs(w.b)) * shown;
    if (size <= 0.0) return;
    g_sight_total += size;
    if (next_random() * g_sight_total >= size) return;
    g_sight_chosen = size;
    g_sight_p = p;
    g_sight_d = d;
    g_sight_n = n;
    g_sight_weight = w;
    g_sight_k = k;
    g_sight_env = env;
    g_sight_lights = lights;
}

vec3 stone_correction() {
    if (g_sight_chosen <= 0.0) return vec3(0.0);
#ifdef FIRE_FIRST_ORDER
    // Fire moved each channel's lookup off the exit's direction; it stays in the cube's part,
    // so the cube is taken again along the exit's own.
    vec3 counted = environment(g_sight_p, g_sight_d) + g_sight_lights;
#else
    vec3 counted = g_sight_env + g_sight_lights;
#endif
    vec3 n = u_frame_rotation * g_sight_n;
    vec3 o = u_frame_rotation * g_sight_p + u_frame_origin + n * u_ray_offset_mm;
    bool met;
    vec3 seen = path_radiance(o, u_frame_rotation * g_sight_d, g_sight_k, n, met);
    return float(kSightFrames) * (g_sight_total / g_sight_chosen) * g_sight_weight *
           (seen - counted);
}
#endif
