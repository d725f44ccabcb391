// The bar view: each bar coloured by its axial stress at the animation time (field.wgsl is
// prepended: the Bar record, the history and the field functions).

@fragment
fn fs_main(in: VertexOut) -> @location(0) vec4<f32> {
    let b = bars[in.bar];
    let stress = stress_at(b, in.distance_m, u.time);
    var rgb = diverging(stress * b.inv_stress_scale);
    if (in.distance_m < b.zone_length) {
        rgb = rgb * 0.8;
    }
    return vec4<f32>(rgb, 1.0);
}
