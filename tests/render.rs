//! The stress-wave view rendered without egui or a window: the wgpu pipeline draws into an
//! offscreen texture, and the pixels are checked against the wave field computed on the CPU
//! (`BarWaves::stress_pa` through the same colour map) and against a stored snapshot.
//!
//! Needs a wgpu adapter; Mesa's software Vulkan (lavapipe) is enough. Without one the test skips,
//! except under `CI=true`, where a missing adapter is a failure.
#![cfg(feature = "gui")]

use eframe::egui_wgpu::wgpu;
use pounding::io::preset::load_for;
use pounding::io::settings::ImpactSetup;
use pounding::model::impact::solve;
use pounding::render::bars::{BarsLayout, GpuHistory, View, XtShown, diverging};
use pounding::render::offscreen::{FieldPart, Offscreen};
use std::path::Path;

mod common;

const W: u32 = 1024;
const H: u32 = 128;
const CLEAR: [f64; 3] = [0.1, 0.1, 0.1];

fn device() -> Option<(wgpu::Device, wgpu::Queue, String)> {
    let adapter = common::adapter_or_skip()?;
    let name = format!("{:?}", adapter.get_info());
    let (device, queue) = pollster::block_on(adapter.request_device(&wgpu::DeviceDescriptor {
        label: Some("render test"),
        ..Default::default()
    }))
    .expect("the adapter gives a device");
    Some((device, queue, name))
}

/// Renders the paper's base case at time `t`; returns RGBA rows and the layout.
fn render(t: f64) -> Option<(Vec<u8>, BarsLayout, ImpactSetup)> {
    let (device, queue, _) = device()?;
    let setup: ImpactSetup = load_for("paper-base", "impact").expect("embedded preset");
    let result = solve(setup.model, &setup.scenario).expect("base case solves");
    let waves = result.waves.as_ref().expect("Sears gives a wave field");
    let history = GpuHistory::from_waves(waves);
    let layout = BarsLayout::new(waves, setup.scenario.approach_velocity_m_s(), &history);
    let pixels = draw_offscreen(
        &device,
        &queue,
        (W, H),
        View::Bars,
        &layout.uniforms(t),
        &layout.bars,
        &history,
    );
    Some((pixels, layout, setup))
}

/// Draws `bars` as `view` over a `size` offscreen target cleared to CLEAR (the library's
/// offscreen drawing, as animations use it); its RGBA rows.
fn draw_offscreen(
    device: &wgpu::Device,
    queue: &wgpu::Queue,
    (w, h): (u32, u32),
    view: View,
    uniforms: &pounding::render::bars::GpuUniforms,
    bars: &[pounding::render::bars::GpuBar],
    history: &GpuHistory,
) -> Vec<u8> {
    let mut target =
        Offscreen::new(device.clone(), queue.clone(), (w, h)).expect("an offscreen target");
    target
        .draw_fields(
            CLEAR,
            &[FieldPart {
                rect: [0, 0, w, h],
                view,
                uniforms: *uniforms,
                bars,
                history,
            }],
        )
        .expect("the frame reads back")
}

fn pixel(pixels: &[u8], px: u32, py: u32) -> [f64; 3] {
    let i = ((py * W + px) * 4) as usize;
    [0, 1, 2].map(|c| pixels[i + c] as f64 / 255.0)
}

/// World x at the centre of pixel column `px`, and the pixel row at the bars' mid-height.
fn world_x(layout: &BarsLayout, px: u32) -> f64 {
    layout.left + (px as f64 + 0.5) / W as f64 * (layout.right - layout.left)
}

fn mid_row(layout: &BarsLayout) -> u32 {
    let y = 0.5 * (layout.bars[0].y_bottom + layout.bars[0].y_top) as f64;
    ((layout.top - y) / (layout.top - layout.bottom) * H as f64) as u32
}

#[test]
fn gpu_colours_match_the_cpu_wave_field_and_the_front_sits_at_c_t() {
    // 0.3 ms into the base case: bar 2 (2 m) carries a compression front c t = 1.55 m from the
    // contact and is stress-free beyond it.
    let t = 0.3e-3;
    let Some((pixels, layout, setup)) = render(t) else {
        return;
    };
    let result = solve(setup.model, &setup.scenario).unwrap();
    let waves = result.waves.as_ref().unwrap();
    let row = mid_row(&layout);
    let mut worst: f64 = 0.0;
    let mut checked = 0;
    for px in 0..W {
        let x = world_x(&layout, px);
        let (i, dist_world) = if x < 0.0 {
            (0, -x - layout.gap)
        } else {
            (1, x - layout.gap)
        };
        let metres = dist_world / layout.world_per_metre[i];
        let wv = &waves[i];
        // One pixel away from the bar's ends, so the pixel is wholly inside.
        let px_m = (layout.right - layout.left) / W as f64 / layout.world_per_metre[i];
        let got = pixel(&pixels, px, row);
        if metres < -px_m || metres > wv.length_m() + px_m {
            assert!(
                got.iter().all(|c| (c - CLEAR[0]).abs() < 0.02),
                "background at column {px} is {got:?}"
            );
            continue;
        }
        if metres < px_m || metres > wv.length_m() - px_m {
            continue;
        }
        let s = wv.stress_pa(metres, t) * layout.bars[i].inv_stress_scale as f64;
        let mut want = diverging(s as f32).map(|c| c as f64);
        if metres < wv.zone_length_m {
            want = want.map(|c| c * 0.8);
        }
        let err = (0..3).map(|c| (got[c] - want[c]).abs()).fold(0.0, f64::max);
        worst = worst.max(err);
        checked += 1;
    }
    assert!(
        checked > W as usize / 2,
        "only {checked} columns on the bars"
    );
    // 8-bit output (half a level) plus f32 time and interpolation in the shader.
    assert!(worst < 3.0 / 255.0, "worst channel error {worst}");

    // Physics, from the pixels alone: blue (compression) at bar 2's contact end, neutral at its
    // far end, and the front within a few pixels of c t.
    let c = waves[1].wave_speed_m_s;
    let column = |m: f64| {
        let x = layout.gap + m * layout.world_per_metre[1];
        ((x - layout.left) / (layout.right - layout.left) * W as f64) as u32
    };
    let near = pixel(&pixels, column(0.05), row);
    assert!(
        near[2] - near[0] > 0.3,
        "contact end not compressed: {near:?}"
    );
    let far = pixel(&pixels, column(1.95), row);
    let neutral = diverging(0.0).map(|c| c as f64);
    assert!(
        (0..3).all(|k| (far[k] - neutral[k]).abs() < 2.0 / 255.0),
        "far end not stress-free: {far:?}"
    );
    // The front: the last column (from the contact outwards) that is visibly stressed.
    let stressed = |px: u32| {
        let p = pixel(&pixels, px, row);
        (0..3).any(|k| (p[k] - neutral[k]).abs() > 2.0 / 255.0)
    };
    let front_px = (column(0.05)..column(1.95))
        .rev()
        .find(|&px| stressed(px))
        .expect("a front");
    let front_m = (world_x(&layout, front_px) - layout.gap) / layout.world_per_metre[1];
    assert!(
        front_m < c * t && front_m > c * t - 0.1,
        "front at {front_m:.3} m, c t = {:.3} m",
        c * t
    );
}

#[test]
fn bars_view_matches_its_snapshot() {
    let Some((pixels, _, _)) = render(0.3e-3) else {
        return;
    };
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/snapshots/bars-view.png");
    if std::env::var_os("UPDATE_SNAPSHOTS").is_some()
        || !path.exists() && std::env::var_os("CI").is_none()
    {
        write_png(&path, &pixels);
        eprintln!("wrote {}", path.display());
        return;
    }
    assert!(
        path.exists(),
        "snapshot missing (UPDATE_SNAPSHOTS=1 writes it)"
    );
    let (width, height, _, stored) = common::read_png(&path);
    assert_eq!((width, height), (W, H), "snapshot size");
    // Rasterizer noise moves a few edge pixels by a few levels; a missing bar, a wrong colour
    // map or a shifted front changes thousands of pixels by far more.
    let differing = pixels
        .chunks(4)
        .zip(stored.chunks(4))
        .filter(|(a, b)| a.iter().zip(b.iter()).any(|(x, y)| x.abs_diff(*y) > 8))
        .count();
    if differing > (W * H) as usize / 500 {
        write_png(&path.with_extension("new.png"), &pixels);
        panic!(
            "{differing} pixels differ from {}; see bars-view.new.png",
            path.display()
        );
    }
}

fn write_png(path: &Path, rgba: &[u8]) {
    pounding::export::plot::write_png(path, (W, H), png::ColorType::Rgba, rgba)
        .expect("PNG written");
}

#[test]
fn gpu_space_time_diagram_matches_the_cpu_field_and_its_fronts_lie_on_x_equals_c_t() {
    // Wave theory, 1 m on 2 m of steel: every front is a sharp line of slope 1/c.
    let Some((device, queue, _)) = device() else {
        return;
    };
    let mut sc = pounding::model::scenario::ImpactScenario::default();
    sc.bar2.length_m = 2.0;
    let result = solve(pounding::model::impact::ModelKind::Wave, &sc).expect("solves");
    let waves = result.waves.as_ref().unwrap();
    let history = GpuHistory::from_waves(waves);
    let layout = BarsLayout::new(waves, sc.approach_velocity_m_s(), &history).xt();
    let (w, h) = (1024u32, 512u32);
    let span = result.view_span_s();
    for (field, shown) in [(XtShown::Stress, "stress"), (XtShown::Velocity, "velocity")] {
        let pixels = draw_offscreen(
            &device,
            &queue,
            (w, h),
            View::Xt,
            &layout.xt_uniforms(0.0, span, field),
            &layout.bars,
            &history,
        );
        let at = |px: u32, py: u32| {
            let i = ((py * w + px) * 4) as usize;
            [0, 1, 2].map(|c| pixels[i + c] as f64 / 255.0)
        };
        // Pixel centres to world x and time (row 0 at the top: the latest time).
        let x_of =
            |px: u32| layout.left + (px as f64 + 0.5) / w as f64 * (layout.right - layout.left);
        let t_of = |py: u32| span * (1.0 - (py as f64 + 0.5) / h as f64);
        let c = waves[1].wave_speed_m_s;
        let (dx, dt) = ((layout.right - layout.left) / w as f64, span / h as f64);
        let (mut worst, mut checked) = (0.0f64, 0);
        for py in 0..h {
            let t = t_of(py);
            for px in 0..w {
                let x = x_of(px);
                let i = if x < 0.0 { 0 } else { 1 };
                let d = (x.abs() - layout.gap) / layout.world_per_metre[i];
                let wv = &waves[i];
                if d < dx || d > wv.length_m() - dx {
                    continue;
                }
                // Away from the fronts by two pixels: in x (dx) and in time (dt, at speed c).
                let margin = 2.0 * (dx / layout.world_per_metre[i] + c * dt);
                let trip = wv.round_trip_s();
                let near_front = (0..8).any(|m| {
                    let s = t - m as f64 * 2.0 * 1.0 / c;
                    [s * c, 2.0 * wv.length_m() - s * c, s * c - trip * c]
                        .iter()
                        .any(|f| (f - d).abs() < margin)
                }) || (0..8).any(|m| {
                    // Bar 2's fronts: the pulse's head and tail, out and back.
                    let s = t - m as f64 * trip;
                    let t1 = 2.0 / c;
                    [
                        s * c,
                        (s - t1) * c,
                        2.0 * wv.length_m() - s * c,
                        2.0 * wv.length_m() - (s - t1) * c,
                    ]
                    .iter()
                    .any(|f| (f - d).abs() < margin)
                });
                if near_front {
                    continue;
                }
                let v = match field {
                    XtShown::Stress => wv.stress_pa(d, t) * layout.bars[i].inv_stress_scale as f64,
                    XtShown::Velocity => {
                        wv.velocity_m_s(d, t) * layout.bars[i].inv_velocity_scale as f64
                    }
                };
                let want = diverging(v as f32).map(|c| c as f64);
                let got = at(px, py);
                worst = worst.max((0..3).map(|k| (got[k] - want[k]).abs()).fold(0.0, f64::max));
                checked += 1;
            }
        }
        eprintln!(
            "x-t {shown}: {checked} pixels against the CPU field, worst channel error {worst:.4}"
        );
        assert!(
            checked > (w * h) as usize / 3,
            "{shown}: only {checked} pixels checked"
        );
        assert!(worst < 3.0 / 255.0, "{shown}: worst channel error {worst}");
        if field == XtShown::Stress {
            // Bar 2's first front, row by row before it reaches the far end: the first column
            // from the contact that is stress-free lies within one pixel of x = c t.
            let neutral = diverging(0.0).map(|c| c as f64);
            let mut rows = 0;
            for py in 0..h {
                let t = t_of(py);
                if !(0.05 * 2.0 / c..0.9 * 2.0 / c).contains(&t) {
                    continue;
                }
                let front_x = layout.gap + c * t * layout.world_per_metre[1];
                let first_free = (0..w)
                    .filter(|&px| x_of(px) > layout.gap + dx)
                    .find(|&px| {
                        let p = at(px, py);
                        (0..3).all(|k| (p[k] - neutral[k]).abs() < 3.0 / 255.0)
                    })
                    .expect("a stress-free pixel ahead of the front");
                assert!(
                    (x_of(first_free) - front_x).abs() <= 1.0 * dx + 1e-12,
                    "row {py} (t = {t:e} s): front at {} against c t at {front_x}",
                    x_of(first_free)
                );
                rows += 1;
            }
            assert!(rows > 100, "only {rows} rows checked");
        }
    }
}

#[test]
fn a_girder_loaded_at_both_ends_is_coloured_by_the_sum_of_both_ends_waves() {
    // Three free girders, the outer two thrown at the middle one: three quarters of L/c after
    // the joints close, the fronts from both ends of the middle girder have met and passed in
    // its middle (compression twice the front's there) and the outer girders carry one front
    // each. The GPU (field.wgsl, kind 2) must paint what the model's two-ended field says.
    use pounding::model::bridge::solve as solve_bridge;
    use pounding::render::bars::{GpuBar, uniforms};
    let Some((device, queue, _)) = device() else {
        return;
    };
    let sc = common::middle_girder_struck_at_both_ends(1.0);
    let still = common::ground_at_rest();
    let r = solve_bridge(&sc, &still).unwrap();
    let g = sc.girder(1);
    let t = 1e-3 + 0.75 * g.length_m / g.wave_speed_m_s();
    let history = GpuHistory::from_pairs(&r.girder_waves);
    let scale = g.impedance_n_s_m() / g.area_m2;
    // The three girders end to end over the world [0, 120] x [0, 1].
    let bars: Vec<GpuBar> = (0..3)
        .map(|i| {
            let (offset, count, _, _) = history.layout[i];
            let w = &r.girder_waves[i][0];
            GpuBar {
                origin_x: 40.0 * i as f32,
                direction: 1.0,
                inv_stress_scale: (1.0 / scale) as f32,
                y_bottom: 0.0,
                y_top: 1.0,
                world_per_metre: 1.0,
                kind: 2,
                aux_offset: offset + count,
                ..GpuBar::of_waves(w, history.layout[i], 1.0)
            }
        })
        .collect();
    let pixels = draw_offscreen(
        &device,
        &queue,
        (W, H),
        View::Bars,
        &uniforms([0.0, 120.0, 0.0, 1.0], t, 3),
        &bars,
        &history,
    );
    let (mut worst, mut checked): (f64, usize) = (0.0, 0);
    for px in 0..W {
        let x = (px as f64 + 0.5) / W as f64 * 120.0;
        let (i, along) = ((x / 40.0) as usize, x % 40.0);
        // Away from the girders' ends, where a pixel straddles two girders.
        if !(0.5..39.5).contains(&along) {
            continue;
        }
        // Nor across a front, where the GPU's coarser grid of the history (T / 400) blurs what
        // the model holds on the step's.
        let s = |x: f64| r.girder_stress_pa(i, x, t) / scale;
        if (s(along - 0.5) - s(along + 0.5)).abs() > 0.02 {
            continue;
        }
        let want = diverging(s(along) as f32).map(|c| c as f64);
        let got = pixel(&pixels, px, H / 2);
        let err = (0..3).map(|c| (got[c] - want[c]).abs()).fold(0.0, f64::max);
        worst = worst.max(err);
        checked += 1;
    }
    assert!(
        checked > W as usize * 3 / 4,
        "only {checked} columns checked"
    );
    assert!(worst < 3.0 / 255.0, "worst channel error {worst}");
    // From the pixels alone: the middle of the middle girder is more compressed (bluer) than a
    // point a quarter along, where one front has passed and the other not yet.
    let middle = pixel(&pixels, W / 2, H / 2);
    let quarter = pixel(&pixels, (W as f64 * (40.0 + 6.0) / 120.0) as u32, H / 2);
    assert!(
        middle[2] - middle[0] > quarter[2] - quarter[0] + 0.1,
        "middle {middle:?}, quarter {quarter:?}"
    );
}

/// An adapter whose fragment shaders get no storage buffers (GL ES: Mesa's llvmpipe through GL
/// among them) cannot draw the stress views: it is refused with the reason, where wgpu would
/// stop the program; one with two or more is taken.
#[test]
fn an_adapter_without_storage_buffers_for_the_field_shaders_is_refused_with_the_reason() {
    let Some(adapter) = common::adapter_or_skip() else {
        return;
    };
    let device_with = |buffers: u32| {
        let limits = wgpu::Limits {
            max_storage_buffers_per_shader_stage: buffers,
            ..wgpu::Limits::downlevel_defaults()
        };
        pollster::block_on(adapter.request_device(&wgpu::DeviceDescriptor {
            label: Some("limited"),
            required_limits: limits,
            ..Default::default()
        }))
        .expect("a device within the adapter's limits")
        .0
    };
    let refused = pounding::render::bars::can_draw_fields(&device_with(0)).unwrap_err();
    assert!(
        refused.contains("0 storage buffers") && refused.contains("need 2"),
        "{refused}"
    );
    assert!(pounding::render::bars::can_draw_fields(&device_with(1)).is_err());
    assert_eq!(
        pounding::render::bars::can_draw_fields(&device_with(4)),
        Ok(())
    );
}
