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
use pounding::render::bars::{BarsLayout, FieldResources, GpuHistory, View, diverging};
use std::path::Path;

mod common;

const W: u32 = 1024;
const H: u32 = 128;
const FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8Unorm;
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
    let mut bars = FieldResources::new(&device, FORMAT);
    bars.upload(
        &device,
        &queue,
        0,
        &layout.uniforms(t),
        &layout.bars,
        &history,
    );

    let texture = device.create_texture(&wgpu::TextureDescriptor {
        label: Some("offscreen"),
        size: wgpu::Extent3d {
            width: W,
            height: H,
            depth_or_array_layers: 1,
        },
        mip_level_count: 1,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format: FORMAT,
        usage: wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC,
        view_formats: &[],
    });
    let view = texture.create_view(&Default::default());
    let readback = device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("readback"),
        size: (W * H * 4) as u64,
        usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
        mapped_at_creation: false,
    });
    let mut encoder = device.create_command_encoder(&Default::default());
    {
        let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("bars"),
            color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                view: &view,
                depth_slice: None,
                resolve_target: None,
                ops: wgpu::Operations {
                    load: wgpu::LoadOp::Clear(wgpu::Color {
                        r: CLEAR[0],
                        g: CLEAR[1],
                        b: CLEAR[2],
                        a: 1.0,
                    }),
                    store: wgpu::StoreOp::Store,
                },
            })],
            depth_stencil_attachment: None,
            timestamp_writes: None,
            occlusion_query_set: None,
            multiview_mask: None,
        });
        bars.draw(&mut pass, 0, View::Bars, 2);
    }
    // W * 4 is a multiple of 256, so rows need no padding.
    encoder.copy_texture_to_buffer(
        wgpu::TexelCopyTextureInfo {
            texture: &texture,
            mip_level: 0,
            origin: wgpu::Origin3d::ZERO,
            aspect: wgpu::TextureAspect::All,
        },
        wgpu::TexelCopyBufferInfo {
            buffer: &readback,
            layout: wgpu::TexelCopyBufferLayout {
                offset: 0,
                bytes_per_row: Some(W * 4),
                rows_per_image: Some(H),
            },
        },
        wgpu::Extent3d {
            width: W,
            height: H,
            depth_or_array_layers: 1,
        },
    );
    queue.submit([encoder.finish()]);
    let slice = readback.slice(..);
    slice.map_async(wgpu::MapMode::Read, |r| r.expect("readback maps"));
    device
        .poll(wgpu::PollType::wait_indefinitely())
        .expect("the GPU finishes");
    let pixels = slice.get_mapped_range().expect("mapped").to_vec();
    Some((pixels, layout, setup))
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
