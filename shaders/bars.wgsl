// Stress waves in the bars, evaluated per fragment from each bar's wave history H(t).
//
// d'Alembert for a free-free bar loaded at its end x = 0 (T = 2L/c the round trip):
//   axial force N(x, t) = H(t - x/c) - H(t - (2L - x)/c)   (compression positive),
// and in a massless contact zone ahead of the body (collocated reading) N = F(t) = H(t) - H(t - T).
// H is uploaded once per solve; per frame only the time changes.

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
};

struct Uniforms {
    view: mat4x4<f32>,
    time: f32,
    bar_count: u32,
    _pad0: f32,
    _pad1: f32,
};

@group(0) @binding(0) var<uniform> u: Uniforms;
@group(0) @binding(1) var<storage, read> history: array<f32>;
@group(0) @binding(2) var<storage, read> bars: array<Bar>;

struct VertexOut {
    @builtin(position) position: vec4<f32>,
    @location(0) distance_m: f32,
    @location(1) @interpolate(flat) bar: u32,
};

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
    out.bar = bar;
    return out;
}

// exp(-travel / t_d): what damping leaves of a wave after `travel` seconds.
fn attenuation(b: Bar, travel: f32) -> f32 {
    return exp(-travel * b.decay_per_s);
}

// H(t): zero before the impact; after the simulated span each round trip repeats the last,
// attenuated by the damping.
fn history_at(b: Bar, t_in: f32) -> f32 {
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
    let p = t / b.dt;
    let i = u32(floor(p));
    if (i + 1u >= b.count) {
        return weight * history[b.offset + b.count - 1u];
    }
    let f = p - floor(p);
    return weight * mix(history[b.offset + i], history[b.offset + i + 1u], f);
}

// Diverging map: compression blue, tension red, stress-free pale grey.
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

@fragment
fn fs_main(in: VertexOut) -> @location(0) vec4<f32> {
    let b = bars[in.bar];
    let x = in.distance_m - b.zone_length;
    var force = 0.0;
    if (x < 0.0) {
        force = history_at(b, u.time) - attenuation(b, b.round_trip) * history_at(b, u.time - b.round_trip);
    } else {
        let xs = min(x, b.body_length);
        let near = xs / b.wave_speed;
        let far = (2.0 * b.body_length - xs) / b.wave_speed;
        force = attenuation(b, near) * history_at(b, u.time - near) - attenuation(b, far) * history_at(b, u.time - far);
    }
    // Tension positive.
    let stress = -force * b.inv_area;
    var rgb = diverging(stress * b.inv_stress_scale);
    if (x < 0.0) {
        rgb = rgb * 0.8;
    }
    return vec4<f32>(rgb, 1.0);
}
