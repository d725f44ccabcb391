// The wave field of a set of bars, shared by the bar view (bars.wgsl) and the space-time
// diagram (xt.wgsl): each bar's history H(t) in one storage buffer, evaluated per fragment.
//
// d'Alembert for a free-free bar loaded at its end x = 0 (T = 2L/c the round trip):
//   axial force N(x, t) = H(t - x/c) - H(t - (2L - x)/c)   (compression positive),
//   particle velocity v(x, t) = v0 + push (H(t - x/c) + H(t - (2L - x)/c)) / Z,
// and in a massless contact zone ahead of the body (collocated reading) N = F(t) = H(t) - H(t - T).
// A lumped body (kind 1) is its uniform-stress equivalent: the history holds F(t), and a second
// one, at aux_offset, the impulse J(t): N = F everywhere, v = v0 + push J / m.
// A bar loaded at both ends (kind 2, a bridge girder) holds the history of its end x = 0 and,
// at aux_offset on the same grid, that of its far end: the field is the sum of the two ends'
// d'Alembert fields, the far end's read at the distance from it and pushing the other way.

struct Bar {
    origin_x: f32,          // world x of the impacting end
    direction: f32,         // +1: the bar extends towards +x, -1 towards -x
    body_length: f32,       // m
    zone_length: f32,       // m, massless zone before the body (collocated), else 0
    wave_speed: f32,        // m/s
    round_trip: f32,        // s
    dt: f32,                // s, history sample spacing
    end_time: f32,          // s, last history sample
    offset: u32,            // first sample in `history`
    count: u32,             // samples
    inv_area: f32,          // 1/m^2
    inv_stress_scale: f32,  // 1/Pa: stress that saturates the colour map
    y_bottom: f32,          // world
    y_top: f32,
    world_per_metre: f32,
    decay_per_s: f32,       // 1/s: material damping, arrivals attenuate as exp(-travel * decay)
    inv_impedance: f32,     // 1/(N s/m)
    initial_velocity: f32,  // m/s, lab frame
    push_direction: f32,    // +1 when the contact pushes the bar towards +x
    inv_velocity_scale: f32, // s/m: velocity that saturates the colour map
    kind: u32,              // 0: d'Alembert bar, 1: lumped body, 2: loaded at both ends
    aux_offset: u32,        // kind 1: the impulse history; kind 2: the far end's history
    inv_mass: f32,          // kind 1: 1/kg
    _pad: f32,
};

struct Uniforms {
    view: mat4x4<f32>,
    time: f32,              // the bar view's instant [s]
    bar_count: u32,
    field: u32,             // the x-t diagram's field: 0 stress, 1 velocity
    t_start: f32,           // the x-t diagram's time axis [s]: t_start at y_bottom
    t_span: f32,            // ... t_start + t_span at y_top
    _pad0: f32,
    _pad1: f32,
    _pad2: f32,
};

@group(0) @binding(0) var<uniform> u: Uniforms;
@group(0) @binding(1) var<storage, read> history: array<f32>;
@group(0) @binding(2) var<storage, read> bars: array<Bar>;

// exp(-travel / t_d): what damping leaves of a wave after `travel` seconds.
fn attenuation(b: Bar, travel: f32) -> f32 {
    return exp(-travel * b.decay_per_s);
}

// Linear interpolation of the samples from `offset`; zero before 0, the last held after.
fn sample(b: Bar, offset: u32, t: f32) -> f32 {
    if (t < 0.0) {
        return 0.0;
    }
    let p = t / b.dt;
    let i = u32(floor(p));
    if (i + 1u >= b.count) {
        return history[offset + b.count - 1u];
    }
    let f = p - floor(p);
    return mix(history[offset + i], history[offset + i + 1u], f);
}

// H(t) of the history at `offset`: zero before the impact; after the simulated span each round
// trip repeats the last, attenuated by the damping. One look-up: the work per pixel does not
// grow with the history.
fn history_from(b: Bar, offset: u32, t_in: f32) -> f32 {
    var t = t_in;
    var weight = 1.0;
    if (t < 0.0) {
        return 0.0;
    }
    if (t > b.end_time && b.round_trip > 0.0) {
        let k = ceil((t - b.end_time) / b.round_trip);
        t = t - k * b.round_trip;
        weight = attenuation(b, k * b.round_trip);
        if (t < 0.0) {
            return 0.0;
        }
    }
    return weight * sample(b, offset, t);
}

fn history_at(b: Bar, t: f32) -> f32 {
    return history_from(b, b.offset, t);
}

// The arrivals at distance x into the body from the end whose history is at `offset`: direct
// (H(t - x/c)) and reflected from the other end (H(t - (2L - x)/c)), each attenuated.
fn arrivals(b: Bar, offset: u32, x: f32, t: f32) -> vec2<f32> {
    let xs = clamp(x, 0.0, b.body_length);
    let near = xs / b.wave_speed;
    let far = (2.0 * b.body_length - xs) / b.wave_speed;
    return vec2<f32>(
        attenuation(b, near) * history_from(b, offset, t - near),
        attenuation(b, far) * history_from(b, offset, t - far),
    );
}

// Axial force at distance `d` from the impacting end (zone included), compression positive.
fn force_at(b: Bar, d: f32, t: f32) -> f32 {
    if (b.kind == 1u) {
        return sample(b, b.offset, t);
    }
    let x = d - b.zone_length;
    if (x < 0.0) {
        return history_at(b, t) - attenuation(b, b.round_trip) * history_at(b, t - b.round_trip);
    }
    let own = arrivals(b, b.offset, x, t);
    var n = own.x - own.y;
    if (b.kind == 2u) {
        let other = arrivals(b, b.aux_offset, b.body_length - x, t);
        n = n + other.x - other.y;
    }
    return n;
}

// Axial stress, tension positive [Pa].
fn stress_at(b: Bar, d: f32, t: f32) -> f32 {
    return -force_at(b, d, t) * b.inv_area;
}

// Particle velocity in the lab frame, positive to the right [m/s].
fn velocity_at(b: Bar, d: f32, t: f32) -> f32 {
    if (b.kind == 1u) {
        return b.initial_velocity + b.push_direction * sample(b, b.aux_offset, t) * b.inv_mass;
    }
    let x = d - b.zone_length;
    let own = arrivals(b, b.offset, x, t);
    var g = own.x + own.y;
    if (b.kind == 2u) {
        let other = arrivals(b, b.aux_offset, b.body_length - x, t);
        g = g - other.x - other.y;
    }
    return b.initial_velocity + b.push_direction * g * b.inv_impedance;
}

// Diverging map: negative (compression, leftward) blue, positive red, zero pale grey.
fn diverging(s: f32) -> vec3<f32> {
    let neutral = vec3<f32>(0.90, 0.90, 0.88);
    let compression = vec3<f32>(0.10, 0.30, 0.85);
    let tension = vec3<f32>(0.85, 0.15, 0.10);
    let a = pow(clamp(abs(s), 0.0, 1.0), 0.7);
    if (s < 0.0) {
        return mix(neutral, compression, a);
    }
    return mix(neutral, tension, a);
}

struct VertexOut {
    @builtin(position) position: vec4<f32>,
    @location(0) distance_m: f32,
    @location(1) height: f32,
    @location(2) @interpolate(flat) bar: u32,
};

// A bar's quad: along the bar from its impacting end, from y_bottom to y_top.
@vertex
fn vs_main(@builtin(vertex_index) vi: u32, @builtin(instance_index) bar: u32) -> VertexOut {
    // Two triangles: (0,0) (1,0) (1,1) / (0,0) (1,1) (0,1).
    var corners = array<vec2<f32>, 6>(
        vec2<f32>(0.0, 0.0), vec2<f32>(1.0, 0.0), vec2<f32>(1.0, 1.0),
        vec2<f32>(0.0, 0.0), vec2<f32>(1.0, 1.0), vec2<f32>(0.0, 1.0),
    );
    let b = bars[bar];
    let c = corners[vi];
    let length_m = b.zone_length + b.body_length;
    let x = b.origin_x + b.direction * c.x * length_m * b.world_per_metre;
    let y = mix(b.y_bottom, b.y_top, c.y);
    var out: VertexOut;
    out.position = u.view * vec4<f32>(x, y, 0.0, 1.0);
    out.distance_m = c.x * length_m;
    out.height = c.y;
    out.bar = bar;
    return out;
}
