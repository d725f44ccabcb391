//! The space-time diagram on the GPU: milliseconds per frame to draw a 1000 x 600 diagram (the
//! fragment work, submitted and waited for), on whatever adapter wgpu finds (Mesa's lavapipe on
//! a machine without a GPU). Against the length of the history: the work per pixel is a fixed
//! number of look-ups into the summed history H, so a history 20 times longer costs the same.

use criterion::{Criterion, criterion_group, criterion_main};
use eframe::egui_wgpu::wgpu;
use pounding::model::impact::{ModelKind, solve};
use pounding::model::scenario::ImpactScenario;
use pounding::render::bars::{BarsLayout, FieldResources, GpuHistory, View, XtShown};

fn device() -> Option<(wgpu::Device, wgpu::Queue)> {
    let instance =
        wgpu::Instance::new(wgpu::InstanceDescriptor::new_without_display_handle_from_env());
    let adapter = pollster::block_on(instance.request_adapter(&wgpu::RequestAdapterOptions {
        power_preference: wgpu::PowerPreference::LowPower,
        ..Default::default()
    }))
    .ok()?;
    eprintln!("adapter: {:?}", adapter.get_info().name);
    pollster::block_on(adapter.request_device(&wgpu::DeviceDescriptor::default())).ok()
}

fn xt_frame(c: &mut Criterion) {
    let Some((device, queue)) = device() else {
        eprintln!("no wgpu adapter: the x-t benchmark is skipped");
        return;
    };
    let (w, h) = (1000u32, 600u32);
    let format = wgpu::TextureFormat::Rgba8Unorm;
    let texture = device.create_texture(&wgpu::TextureDescriptor {
        label: Some("x-t"),
        size: wgpu::Extent3d {
            width: w,
            height: h,
            depth_or_array_layers: 1,
        },
        mip_level_count: 1,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format,
        usage: wgpu::TextureUsages::RENDER_ATTACHMENT,
        view_formats: &[],
    });
    let view = texture.create_view(&Default::default());
    let mut g = c.benchmark_group("xt_frame_1000x600");
    g.sample_size(20);
    // The base case (1034 steps), and the same bars simulated 20 times longer (20 000 steps of
    // history, about 26 round trips of bar 1).
    for (name, window) in [("base_case", 0.0), ("history_x20", 20_000.0 * 1e-6)] {
        let mut sc = ImpactScenario::default();
        sc.solver.window_s = window;
        let r = solve(ModelKind::Sears, &sc).expect("solves");
        let waves = r.waves.as_ref().unwrap();
        let history = GpuHistory::from_waves(waves);
        let layout = BarsLayout::new(waves, sc.approach_velocity_m_s(), &history).xt();
        let mut resources = FieldResources::new(&device, format);
        let span = r.view_span_s();
        let mut k = 0u32;
        g.bench_function(name, |b| {
            b.iter(|| {
                // A new time axis every frame, as while a slider drags: only uniforms change.
                k += 1;
                let uniforms =
                    layout.xt_uniforms(0.0, span * (1.0 + 1e-3 * (k % 7) as f64), XtShown::Stress);
                resources.upload(&device, &queue, 0, &uniforms, &layout.bars, &history);
                let mut encoder = device.create_command_encoder(&Default::default());
                {
                    let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
                        label: Some("x-t"),
                        color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                            view: &view,
                            depth_slice: None,
                            resolve_target: None,
                            ops: wgpu::Operations {
                                load: wgpu::LoadOp::Clear(wgpu::Color::BLACK),
                                store: wgpu::StoreOp::Store,
                            },
                        })],
                        depth_stencil_attachment: None,
                        timestamp_writes: None,
                        occlusion_query_set: None,
                        multiview_mask: None,
                    });
                    resources.draw(&mut pass, 0, View::Xt, 2);
                }
                queue.submit([encoder.finish()]);
                device
                    .poll(wgpu::PollType::wait_indefinitely())
                    .expect("the frame finishes");
            })
        });
    }
    g.finish();
}

criterion_group!(benches, xt_frame);
criterion_main!(benches);
