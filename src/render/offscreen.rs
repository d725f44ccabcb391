//! The window's wgpu drawing without a window: the wave-field pipelines (and egui's own
//! renderer, for views painted with egui) drawn into an offscreen texture and read back as RGBA
//! rows. Animations, tests and benchmarks render through this, on any adapter wgpu finds
//! (Mesa's software lavapipe included).

use super::bars::{FieldResources, GpuBar, GpuHistory, GpuUniforms, View};
use eframe::egui;
use eframe::egui_wgpu::{self, wgpu};

pub use crate::export::animation::SIDE_RANGE;

/// The texture format of every offscreen target: 8-bit RGBA, no sRGB encoding, so a pixel holds
/// exactly what the shader wrote (as in the window).
pub const FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8Unorm;

#[derive(Debug, thiserror::Error)]
pub enum OffscreenError {
    #[error("no wgpu adapter (a GPU, or Mesa's software lavapipe): {0}")]
    NoAdapter(String),
    #[error("the wgpu adapter gave no device: {0}")]
    Device(String),
    #[error("pixel size {0}x{1}: each side must be {lo} to {hi}", lo = SIDE_RANGE.start(), hi = SIDE_RANGE.end())]
    Size(u32, u32),
    #[error("reading the frame back failed: {0}")]
    Readback(String),
}

/// The first adapter wgpu finds from the environment (`WGPU_BACKEND`, ...), preferring a low-power
/// one: an integrated GPU, or the software rasterizer on a machine without one.
pub fn headless_device() -> Result<(wgpu::Device, wgpu::Queue, String), OffscreenError> {
    let instance =
        wgpu::Instance::new(wgpu::InstanceDescriptor::new_without_display_handle_from_env());
    let adapter = pollster::block_on(instance.request_adapter(&wgpu::RequestAdapterOptions {
        power_preference: wgpu::PowerPreference::LowPower,
        ..Default::default()
    }))
    .map_err(|e| OffscreenError::NoAdapter(e.to_string()))?;
    let name = adapter.get_info().name;
    let (device, queue) = pollster::block_on(adapter.request_device(&wgpu::DeviceDescriptor {
        label: Some("offscreen"),
        ..Default::default()
    }))
    .map_err(|e| OffscreenError::Device(e.to_string()))?;
    super::bars::can_draw_fields(&device).map_err(OffscreenError::Device)?;
    Ok((device, queue, name))
}

/// One wave-field view in a frame: where (pixels: x, y from the top left, width, height) and
/// what to draw there.
pub struct FieldPart<'a> {
    pub rect: [u32; 4],
    pub view: View,
    pub uniforms: GpuUniforms,
    pub bars: &'a [GpuBar],
    pub history: &'a GpuHistory,
}

/// An offscreen colour target of one size, with the pipelines that draw into it.
pub struct Offscreen {
    device: wgpu::Device,
    queue: wgpu::Queue,
    size: (u32, u32),
    texture: wgpu::Texture,
    readback: wgpu::Buffer,
    /// Bytes per row in `readback`: wgpu copies rows at multiples of 256 bytes.
    padded_row: u32,
    field: FieldResources,
    /// egui's renderer (with its own copy of the field pipelines for paint callbacks), made on
    /// the first egui frame.
    egui: Option<egui_wgpu::Renderer>,
}

impl Offscreen {
    pub fn new(
        device: wgpu::Device,
        queue: wgpu::Queue,
        (w, h): (u32, u32),
    ) -> Result<Self, OffscreenError> {
        if !SIDE_RANGE.contains(&w) || !SIDE_RANGE.contains(&h) {
            return Err(OffscreenError::Size(w, h));
        }
        let texture = device.create_texture(&wgpu::TextureDescriptor {
            label: Some("offscreen"),
            size: extent(w, h),
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format: FORMAT,
            usage: wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC,
            view_formats: &[],
        });
        let padded_row = (w * 4).div_ceil(256) * 256;
        let readback = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("readback"),
            size: (padded_row * h) as u64,
            usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
            mapped_at_creation: false,
        });
        let field = FieldResources::new(&device, FORMAT);
        Ok(Offscreen {
            device,
            queue,
            size: (w, h),
            texture,
            readback,
            padded_row,
            field,
            egui: None,
        })
    }

    /// On the adapter [`headless_device`] finds.
    pub fn headless(size: (u32, u32)) -> Result<Self, OffscreenError> {
        let (device, queue, _) = headless_device()?;
        Self::new(device, queue, size)
    }

    pub fn size(&self) -> (u32, u32) {
        self.size
    }

    /// Clears the target to `clear` (RGB in [0, 1]), draws each part in its rectangle (slot =
    /// its index) and returns the frame as RGBA rows, top row first.
    pub fn draw_fields(
        &mut self,
        clear: [f64; 3],
        parts: &[FieldPart],
    ) -> Result<Vec<u8>, OffscreenError> {
        for (slot, p) in parts.iter().enumerate() {
            self.field.upload(
                &self.device,
                &self.queue,
                slot as u64,
                &p.uniforms,
                p.bars,
                p.history,
            );
        }
        let view = self.texture.create_view(&Default::default());
        let mut encoder = self.device.create_command_encoder(&Default::default());
        {
            let mut pass = begin_pass(&mut encoder, &view, clear);
            for (slot, p) in parts.iter().enumerate() {
                let [x, y, w, h] = p.rect.map(|v| v as f32);
                pass.set_viewport(x, y, w, h, 0.0, 1.0);
                self.field
                    .draw(&mut pass, slot as u64, p.view, p.bars.len() as u32);
            }
        }
        self.finish(encoder)
    }

    /// Runs one egui frame of `ctx` drawing `ui` over the whole target (`pixels_per_point`) and
    /// renders it, paint callbacks (the wave fields) included, into the target cleared to
    /// `clear`: the window's own drawing, offscreen.
    pub fn draw_egui(
        &mut self,
        ctx: &egui::Context,
        clear: [f64; 3],
        pixels_per_point: f32,
        mut ui: impl FnMut(&mut egui::Ui),
    ) -> Result<Vec<u8>, OffscreenError> {
        let (w, h) = self.size;
        let mut input = egui::RawInput {
            screen_rect: Some(egui::Rect::from_min_size(
                egui::Pos2::ZERO,
                egui::vec2(w as f32, h as f32) / pixels_per_point,
            )),
            ..Default::default()
        };
        input
            .viewports
            .entry(egui::ViewportId::ROOT)
            .or_default()
            .native_pixels_per_point = Some(pixels_per_point);
        let mut output = ctx.run_ui(input, |root| {
            egui::CentralPanel::default()
                .frame(egui::Frame::NONE)
                .show(root, |inner| ui(inner));
        });
        let jobs = ctx.tessellate(output.shapes, output.pixels_per_point);
        let screen = egui_wgpu::ScreenDescriptor {
            size_in_pixels: [w, h],
            pixels_per_point: output.pixels_per_point,
        };
        let (device, queue) = (&self.device, &self.queue);
        let renderer = self.egui.get_or_insert_with(|| {
            let mut r = egui_wgpu::Renderer::new(device, FORMAT, Default::default());
            r.callback_resources
                .insert(FieldResources::new(device, FORMAT));
            r
        });
        for (id, deltas) in &output.textures_delta.set {
            for delta in deltas {
                renderer.update_texture(device, queue, *id, delta);
            }
        }
        let mut encoder = device.create_command_encoder(&Default::default());
        let commands = renderer.update_buffers(device, queue, &mut encoder, &jobs, &screen);
        let view = self.texture.create_view(&Default::default());
        {
            let mut pass = begin_pass(&mut encoder, &view, clear).forget_lifetime();
            renderer.render(&mut pass, &jobs, &screen);
        }
        for id in &output.textures_delta.free {
            renderer.free_texture(id);
        }
        // Every delta is applied above; dropping an unapplied one is a bug egui checks for.
        output.textures_delta.clear();
        queue.submit(commands);
        self.finish(encoder)
    }

    /// Copies the target to the readback buffer, submits, waits and returns tight RGBA rows.
    fn finish(&self, mut encoder: wgpu::CommandEncoder) -> Result<Vec<u8>, OffscreenError> {
        let (w, h) = self.size;
        encoder.copy_texture_to_buffer(
            wgpu::TexelCopyTextureInfo {
                texture: &self.texture,
                mip_level: 0,
                origin: wgpu::Origin3d::ZERO,
                aspect: wgpu::TextureAspect::All,
            },
            wgpu::TexelCopyBufferInfo {
                buffer: &self.readback,
                layout: wgpu::TexelCopyBufferLayout {
                    offset: 0,
                    bytes_per_row: Some(self.padded_row),
                    rows_per_image: Some(h),
                },
            },
            extent(w, h),
        );
        self.queue.submit([encoder.finish()]);
        let slice = self.readback.slice(..);
        let (tx, rx) = std::sync::mpsc::channel();
        slice.map_async(wgpu::MapMode::Read, move |r| {
            let _ = tx.send(r);
        });
        self.device
            .poll(wgpu::PollType::wait_indefinitely())
            .map_err(|e| OffscreenError::Readback(e.to_string()))?;
        rx.recv()
            .map_err(|e| OffscreenError::Readback(e.to_string()))?
            .map_err(|e| OffscreenError::Readback(e.to_string()))?;
        let mut rgba = Vec::with_capacity((w * h * 4) as usize);
        {
            let mapped = slice
                .get_mapped_range()
                .map_err(|e| OffscreenError::Readback(e.to_string()))?;
            for row in mapped.chunks(self.padded_row as usize) {
                rgba.extend_from_slice(&row[..(w * 4) as usize]);
            }
        }
        self.readback.unmap();
        Ok(rgba)
    }
}

fn extent(width: u32, height: u32) -> wgpu::Extent3d {
    wgpu::Extent3d {
        width,
        height,
        depth_or_array_layers: 1,
    }
}

fn begin_pass<'e>(
    encoder: &'e mut wgpu::CommandEncoder,
    view: &'e wgpu::TextureView,
    [r, g, b]: [f64; 3],
) -> wgpu::RenderPass<'e> {
    encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
        label: Some("offscreen"),
        color_attachments: &[Some(wgpu::RenderPassColorAttachment {
            view,
            depth_slice: None,
            resolve_target: None,
            ops: wgpu::Operations {
                load: wgpu::LoadOp::Clear(wgpu::Color { r, g, b, a: 1.0 }),
                store: wgpu::StoreOp::Store,
            },
        })],
        depth_stencil_attachment: None,
        timestamp_writes: None,
        occlusion_query_set: None,
        multiview_mask: None,
    })
}
