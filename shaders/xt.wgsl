// The space-time (x-t) diagram: each bar along x, time upward, every pixel coloured by the
// stress or the particle velocity at its (x, t) (field.wgsl is prepended). The same history as
// the bar view; a frame writes only the uniforms.

@fragment
fn fs_main(in: VertexOut) -> @location(0) vec4<f32> {
    let b = bars[in.bar];
    let t = u.t_start + in.height * u.t_span;
    var s = 0.0;
    if (u.field == 0u) {
        s = stress_at(b, in.distance_m, t) * b.inv_stress_scale;
    } else {
        s = velocity_at(b, in.distance_m, t) * b.inv_velocity_scale;
    }
    var rgb = diverging(s);
    if (in.distance_m < b.zone_length) {
        rgb = rgb * 0.8;
    }
    return vec4<f32>(rgb, 1.0);
}
