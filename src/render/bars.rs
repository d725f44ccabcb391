//! The wave-field views on the GPU: the bar view (`shaders/bars.wgsl`: each bar coloured by its
//! axial stress at one instant) and the space-time diagram (`shaders/xt.wgsl`: each bar along x,
//! time upward), both evaluated per fragment from each bar's wave history
//! (`shaders/field.wgsl`). The history goes to the GPU once per solve; a frame writes only the
//! uniforms and the bars' records, so the per-frame CPU cost does not depend on the history's
//! length. Every view on screen has a slot of its own (uniforms, bars, history), so several can
//! be drawn in one frame.

use crate::model::field::{BarWaves, History};
use crate::model::impact::ImpactResult;
use crate::model::scenario::ImpactScenario;
use bytemuck::{Pod, Zeroable};
use eframe::egui_wgpu::{self, wgpu};
use std::sync::Arc;

/// One bar as the shader sees it (WGSL `Bar`, 96 bytes, in a storage buffer: any number).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, Pod, Zeroable)]
pub struct GpuBar {
    pub origin_x: f32,
    pub direction: f32,
    pub body_length: f32,
    pub zone_length: f32,
    pub wave_speed: f32,
    pub round_trip: f32,
    pub dt: f32,
    pub end_time: f32,
    pub offset: u32,
    pub count: u32,
    pub inv_area: f32,
    pub inv_stress_scale: f32,
    pub y_bottom: f32,
    pub y_top: f32,
    pub world_per_metre: f32,
    /// Material damping 1 / t_d [1/s] (0: elastic): arrivals attenuate as exp(-travel / t_d).
    pub decay_per_s: f32,
    pub inv_impedance: f32,
    /// Lab-frame velocity before the impact [m/s].
    pub initial_velocity: f32,
    /// +1 when the contact pushes the bar towards +x.
    pub push_direction: f32,
    /// 1 / the velocity that saturates the colour map [s/m].
    pub inv_velocity_scale: f32,
    /// 0: a d'Alembert bar; 1: a lumped body drawn as its uniform-stress equivalent; 2: a bar
    /// loaded at both ends (a bridge girder, [`GpuHistory::from_pairs`]).
    pub kind: u32,
    /// Kind 1: where its impulse history starts; kind 2: where its far end's history starts.
    pub aux_offset: u32,
    /// Kind 1: 1 / its mass [1/kg].
    pub inv_mass: f32,
    pub _pad: f32,
}

impl GpuBar {
    /// Everything a bar's waves fix: the body, its waves' speed and damping, where its history
    /// lies on the GPU (`layout`, an entry of [`GpuHistory::layout`]) and the velocity fields,
    /// with `v_scale` saturating the colour map. The geometry on screen and the stress scale are
    /// left for the caller.
    pub fn of_waves(w: &BarWaves, (offset, count, dt, end): HistoryEntry, v_scale: f64) -> Self {
        GpuBar {
            body_length: w.body_length_m as f32,
            zone_length: w.zone_length_m as f32,
            wave_speed: w.wave_speed_m_s as f32,
            round_trip: w.round_trip_s() as f32,
            // A history of no samples has no step; the shader divides by it.
            dt: dt.max(1e-12),
            end_time: end,
            offset,
            count,
            inv_area: (1.0 / w.area_m2) as f32,
            decay_per_s: w.decay_per_s as f32,
            inv_impedance: (1.0 / w.impedance_n_s_m) as f32,
            initial_velocity: w.initial_velocity_m_s as f32,
            push_direction: w.push_direction as f32,
            inv_velocity_scale: (1.0 / v_scale.max(1e-30)) as f32,
            ..GpuBar::default()
        }
    }
}

/// The field a space-time diagram shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum XtShown {
    Stress = 0,
    Velocity = 1,
}

/// WGSL `Uniforms` (96 bytes).
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
pub struct GpuUniforms {
    pub view: [[f32; 4]; 4],
    /// The bar view's instant [s].
    pub time: f32,
    pub bar_count: u32,
    /// The diagram's field: 0 stress, 1 velocity.
    pub field: u32,
    /// The diagram's time axis: `t_start` at a bar's y_bottom, `t_start + t_span` at y_top [s].
    pub t_start: f32,
    pub t_span: f32,
    pub _pad: [f32; 3],
}

/// Where one bar's history lies in a [`GpuHistory`]: its first sample, the number of samples,
/// their spacing [s] and the end of the run they cover [s].
pub type HistoryEntry = (u32, u32, f32, f32);

/// The wave histories of a set of bars on uniform grids, ready to upload.
#[derive(Debug, Clone)]
pub struct GpuHistory {
    /// Unique to this history in the process: the GPU copy is keyed by it, so views that share
    /// the pipeline never draw each other's waves.
    pub id: u64,
    pub samples: Vec<f32>,
    /// Each bar's place.
    pub layout: Vec<HistoryEntry>,
}

static NEXT_HISTORY: std::sync::atomic::AtomicU64 = std::sync::atomic::AtomicU64::new(1);

impl Default for GpuHistory {
    fn default() -> Self {
        GpuHistory {
            id: NEXT_HISTORY.fetch_add(1, std::sync::atomic::Ordering::Relaxed),
            samples: Vec::new(),
            layout: Vec::new(),
        }
    }
}

/// Samples per round trip when a step-function history (wave theory) or one stored in stretches
/// (a building slab) is put on a grid.
const STEP_SAMPLES_PER_ROUND_TRIP: f64 = 400.0;

/// The most samples all the bars of one upload take together (16 MB of f32): a long run of many
/// slabs is put on a coarser grid rather than outgrow the GPU's buffer.
const GPU_SAMPLE_BUDGET: f64 = 4.0e6;

impl GpuHistory {
    /// A lumped result's force F(t) and impulse J(t) on `samples` points over [0, t_end]: both
    /// bars read F from offset 0 and J right after it.
    pub fn uniform(r: &ImpactResult, samples: usize, t_end: f64) -> Self {
        let n = samples.max(2);
        let dt = t_end.max(1e-12) / (n - 1) as f64;
        let at = |y: &[f64], k: usize| crate::model::xt::interpolate(&r.time_s, y, k as f64 * dt);
        let mut samples: Vec<f32> = (0..n).map(|k| at(&r.force_n, k) as f32).collect();
        samples.extend((0..n).map(|k| at(&r.impulse_history_ns, k) as f32));
        let entry = (0, n as u32, dt as f32, t_end as f32);
        GpuHistory {
            samples,
            layout: vec![entry, entry],
            ..GpuHistory::default()
        }
    }

    pub fn from_waves(waves: &[BarWaves; 2]) -> Self {
        Self::from_bars(waves.iter())
    }

    /// Any number of bars, in the order their [`GpuBar`]s will be drawn.
    pub fn from_bars<'a>(waves: impl IntoIterator<Item = &'a BarWaves>) -> Self {
        let waves: Vec<&BarWaves> = waves.into_iter().collect();
        let per_bar = GPU_SAMPLE_BUDGET / waves.len().max(1) as f64;
        let mut samples = Vec::new();
        let mut layout = Vec::new();
        for w in waves {
            let offset = samples.len() as u32;
            let dt = match &w.history {
                History::Uniform { dt_s, values } => {
                    samples.extend(values.iter().map(|&v| v as f32));
                    *dt_s
                }
                History::Steps { .. } | History::Segments { .. } => {
                    let (dt, n) = grid(w, per_bar);
                    samples.extend(w.history_on_grid(dt, n).map(|v| v as f32));
                    dt
                }
            };
            let count = samples.len() as u32 - offset;
            if count == 0 {
                samples.push(0.0);
            }
            layout.push((offset, count.max(1), dt as f32, w.end_s as f32));
        }
        GpuHistory {
            samples,
            layout,
            ..GpuHistory::default()
        }
    }

    /// Bars loaded at both ends (bridge girders: the waves from each end, `[0]` from the end
    /// the bar is drawn from), each on one grid: a layout entry per bar for its first end, the
    /// far end's samples right after (a [`GpuBar`] of kind 2 reads them at `offset + count`).
    pub fn from_pairs(pairs: &[[BarWaves; 2]]) -> Self {
        let per_bar = GPU_SAMPLE_BUDGET / (2 * pairs.len()).max(1) as f64;
        let mut samples = Vec::new();
        let mut layout = Vec::new();
        for pair in pairs {
            let offset = samples.len() as u32;
            let (dt, n) = grid(&pair[0], per_bar);
            for w in pair {
                samples.extend(w.history_on_grid(dt, n).map(|v| v as f32));
            }
            layout.push((offset, n as u32, dt as f32, pair[0].end_s as f32));
        }
        GpuHistory {
            samples,
            layout,
            ..GpuHistory::default()
        }
    }
}

/// The grid a history without one of its own (steps, stretches) is put on: its step and its
/// sample count, within a bar's share of the budget.
fn grid(w: &BarWaves, per_bar: f64) -> (f64, usize) {
    let dt = (w.round_trip_s() / STEP_SAMPLES_PER_ROUND_TRIP).max(w.end_s / per_bar);
    (dt, (w.end_s / dt).ceil() as usize + 2)
}

/// Which picture a slot draws.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum View {
    /// The bars at one instant.
    Bars,
    /// The space-time diagram.
    Xt,
}

/// One view's buffers: its uniforms, its bars and the history it draws.
struct Slot {
    uniforms: wgpu::Buffer,
    bars: wgpu::Buffer,
    history: wgpu::Buffer,
    bind_group: wgpu::BindGroup,
    /// The [`GpuHistory::id`] now in `history`.
    history_id: u64,
}

/// The pipelines of both views and a slot per view; they live in egui-wgpu's callback
/// resources.
pub struct FieldResources {
    bars_pipeline: wgpu::RenderPipeline,
    xt_pipeline: wgpu::RenderPipeline,
    layout: wgpu::BindGroupLayout,
    slots: std::collections::HashMap<u64, Slot>,
}

/// Builds the pipelines once, at start-up, and stores them with the renderer.
/// An adapter that cannot run the field shaders is refused with why (GL ES adapters, Mesa's
/// llvmpipe through GL among them, give fragment shaders no storage buffers), never left to
/// fail inside wgpu.
pub fn install(render_state: &egui_wgpu::RenderState) -> Result<(), String> {
    can_draw_fields(&render_state.device)?;
    let resources = FieldResources::new(&render_state.device, render_state.target_format);
    render_state
        .renderer
        .write()
        .callback_resources
        .insert(resources);
    Ok(())
}

/// The field shaders read the bars and the history from two storage buffers in the fragment
/// stage.
pub fn can_draw_fields(device: &wgpu::Device) -> Result<(), String> {
    let have = device.limits().max_storage_buffers_per_shader_stage;
    if have < 2 {
        return Err(format!(
            "this graphics adapter gives a shader {have} storage buffers where the stress views need 2 (a GL ES adapter? WGPU_BACKEND=vulkan picks another where there is one): the stress views are not drawn"
        ));
    }
    Ok(())
}

/// The shader of a view: the shared field code, then the view's fragment stage.
fn shader_source(view: View) -> String {
    let stage = match view {
        View::Bars => include_str!("../../shaders/bars.wgsl"),
        View::Xt => include_str!("../../shaders/xt.wgsl"),
    };
    format!("{}\n{stage}", include_str!("../../shaders/field.wgsl"))
}

impl FieldResources {
    /// The pipelines for a colour target of `format` (the window's, or an offscreen texture's).
    pub fn new(device: &wgpu::Device, format: wgpu::TextureFormat) -> Self {
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("wave field"),
            entries: &[
                wgpu::BindGroupLayoutEntry {
                    binding: 0,
                    visibility: wgpu::ShaderStages::VERTEX_FRAGMENT,
                    ty: wgpu::BindingType::Buffer {
                        ty: wgpu::BufferBindingType::Uniform,
                        has_dynamic_offset: false,
                        min_binding_size: None,
                    },
                    count: None,
                },
                storage_entry(1, wgpu::ShaderStages::FRAGMENT),
                storage_entry(2, wgpu::ShaderStages::VERTEX_FRAGMENT),
            ],
        });
        let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("wave field"),
            bind_group_layouts: &[Some(&layout)],
            immediate_size: 0,
        });
        let pipeline = |view: View| {
            let label = match view {
                View::Bars => "bars",
                View::Xt => "x-t",
            };
            let shader = device.create_shader_module(wgpu::ShaderModuleDescriptor {
                label: Some(label),
                source: wgpu::ShaderSource::Wgsl(shader_source(view).into()),
            });
            device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
                label: Some(label),
                layout: Some(&pipeline_layout),
                vertex: wgpu::VertexState {
                    module: &shader,
                    entry_point: Some("vs_main"),
                    buffers: &[],
                    compilation_options: Default::default(),
                },
                fragment: Some(wgpu::FragmentState {
                    module: &shader,
                    entry_point: Some("fs_main"),
                    targets: &[Some(format.into())],
                    compilation_options: Default::default(),
                }),
                primitive: wgpu::PrimitiveState::default(),
                depth_stencil: None,
                multisample: wgpu::MultisampleState::default(),
                multiview_mask: None,
                cache: None,
            })
        };
        FieldResources {
            bars_pipeline: pipeline(View::Bars),
            xt_pipeline: pipeline(View::Xt),
            layout,
            slots: std::collections::HashMap::new(),
        }
    }

    /// Uploads a frame's uniforms and bars to the view's `slot`, and the history when it is
    /// another one than the slot holds.
    pub fn upload(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        slot: u64,
        uniforms: &GpuUniforms,
        bars: &[GpuBar],
        history: &GpuHistory,
    ) {
        let layout = &self.layout;
        let s = self.slots.entry(slot).or_insert_with(|| {
            let uniforms = device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("wave field uniforms"),
                size: std::mem::size_of::<GpuUniforms>() as u64,
                usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
                mapped_at_creation: false,
            });
            let history = storage_buffer(device, "wave history", 4096);
            let bars = storage_buffer(device, "bars", 16 * std::mem::size_of::<GpuBar>());
            let bind_group = bind(device, layout, &uniforms, &history, &bars);
            Slot {
                uniforms,
                bars,
                history,
                bind_group,
                history_id: 0,
            }
        });
        let mut rebind = false;
        if s.history_id != history.id {
            let bytes = history.samples.len() * 4;
            if bytes as u64 > s.history.size() {
                s.history = storage_buffer(device, "wave history", bytes.next_power_of_two());
                rebind = true;
            }
            if !history.samples.is_empty() {
                queue.write_buffer(&s.history, 0, bytemuck::cast_slice(&history.samples));
            }
            s.history_id = history.id;
        }
        let bytes = std::mem::size_of_val(bars);
        if bytes as u64 > s.bars.size() {
            s.bars = storage_buffer(device, "bars", bytes.next_power_of_two());
            rebind = true;
        }
        if rebind {
            s.bind_group = bind(device, layout, &s.uniforms, &s.history, &s.bars);
        }
        if !bars.is_empty() {
            queue.write_buffer(&s.bars, 0, bytemuck::cast_slice(bars));
        }
        queue.write_buffer(&s.uniforms, 0, bytemuck::bytes_of(uniforms));
    }

    /// Draws a slot's bars as `view` into a pass whose target has the pipelines' format.
    pub fn draw(&self, pass: &mut wgpu::RenderPass<'_>, slot: u64, view: View, bar_count: u32) {
        let Some(s) = self.slots.get(&slot) else {
            return;
        };
        pass.set_pipeline(match view {
            View::Bars => &self.bars_pipeline,
            View::Xt => &self.xt_pipeline,
        });
        pass.set_bind_group(0, &s.bind_group, &[]);
        pass.draw(0..6, 0..bar_count);
    }
}

fn storage_entry(binding: u32, visibility: wgpu::ShaderStages) -> wgpu::BindGroupLayoutEntry {
    wgpu::BindGroupLayoutEntry {
        binding,
        visibility,
        ty: wgpu::BindingType::Buffer {
            ty: wgpu::BufferBindingType::Storage { read_only: true },
            has_dynamic_offset: false,
            min_binding_size: None,
        },
        count: None,
    }
}

fn storage_buffer(device: &wgpu::Device, label: &str, bytes: usize) -> wgpu::Buffer {
    device.create_buffer(&wgpu::BufferDescriptor {
        label: Some(label),
        size: bytes.max(64) as u64,
        usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_DST,
        mapped_at_creation: false,
    })
}

fn bind(
    device: &wgpu::Device,
    layout: &wgpu::BindGroupLayout,
    uniforms: &wgpu::Buffer,
    history: &wgpu::Buffer,
    bars: &wgpu::Buffer,
) -> wgpu::BindGroup {
    device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: Some("wave field"),
        layout,
        entries: &[
            wgpu::BindGroupEntry {
                binding: 0,
                resource: uniforms.as_entire_binding(),
            },
            wgpu::BindGroupEntry {
                binding: 1,
                resource: history.as_entire_binding(),
            },
            wgpu::BindGroupEntry {
                binding: 2,
                resource: bars.as_entire_binding(),
            },
        ],
    })
}

/// One frame's draw of one view: its slot, the uniforms and bars, and the history (uploaded
/// when it is another one than the slot holds).
pub struct BarsCallback {
    pub slot: u64,
    pub view: View,
    pub uniforms: GpuUniforms,
    pub bars: Vec<GpuBar>,
    pub history: Arc<GpuHistory>,
}

impl egui_wgpu::CallbackTrait for BarsCallback {
    fn prepare(
        &self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        _screen: &egui_wgpu::ScreenDescriptor,
        _encoder: &mut wgpu::CommandEncoder,
        resources: &mut egui_wgpu::CallbackResources,
    ) -> Vec<wgpu::CommandBuffer> {
        if let Some(r) = resources.get_mut::<FieldResources>() {
            r.upload(
                device,
                queue,
                self.slot,
                &self.uniforms,
                &self.bars,
                &self.history,
            );
        }
        Vec::new()
    }

    fn paint(
        &self,
        _info: eframe::egui::PaintCallbackInfo,
        pass: &mut wgpu::RenderPass<'static>,
        resources: &egui_wgpu::CallbackResources,
    ) {
        if let Some(r) = resources.get::<FieldResources>() {
            r.draw(pass, self.slot, self.view, self.uniforms.bar_count);
        }
    }
}

/// Where the bars go and how they are coloured: both bars' GPU records and the world rectangle
/// they are shown in. The bars meet at x = 0 (bar 1 to the left), lie between y = 0.40 and 0.62
/// of a unit-high world, and are drawn to scale unless one is 20 times the other.
#[derive(Clone, Copy, Debug)]
pub struct BarsLayout {
    pub bars: [GpuBar; 2],

    /// World x of each bar's impacting end.
    pub gap: f64,
    /// World units per metre of each bar.
    pub world_per_metre: [f64; 2],
    pub to_scale: bool,
    /// Stress that saturates the colour map: the wave-theory stress Z1 Z2/(Z1+Z2) w / A1 [Pa].
    pub stress_scale_pa: f64,
    pub left: f64,
    pub right: f64,
    pub bottom: f64,
    pub top: f64,
}

pub const BAR_Y: (f32, f32) = (0.40, 0.62);

impl BarsLayout {
    /// `approach_m_s` is the closing velocity v1 - v2; the bars are the first two of `gpu`.
    pub fn new(waves: &[BarWaves; 2], approach_m_s: f64, gpu: &GpuHistory) -> Self {
        Self::at_entries(
            [&waves[0], &waves[1]],
            approach_m_s,
            [gpu.layout[0], gpu.layout[1]],
        )
    }

    /// As `new`, the bars read from the given entries of a history's layout (two slabs of a
    /// history that holds more).
    pub fn at_entries(
        waves: [&BarWaves; 2],
        approach_m_s: f64,
        entries: [HistoryEntry; 2],
    ) -> Self {
        let lengths = [waves[0].length_m(), waves[1].length_m()];
        let to_scale = lengths[0].max(lengths[1]) / lengths[0].min(lengths[1]) < 20.0;
        let wpm = if to_scale {
            [1.0, 1.0]
        } else {
            [1.0 / lengths[0], 1.0 / lengths[1]]
        };
        let extent = [lengths[0] * wpm[0], lengths[1] * wpm[1]];
        let gap = 0.006 * (extent[0] + extent[1]);
        let w = approach_m_s.abs().max(1e-12);
        let v_scale = waves
            .iter()
            .map(|b| b.initial_velocity_m_s.abs())
            .fold(w, f64::max);
        let (z1, z2) = (waves[0].impedance_n_s_m, waves[1].impedance_n_s_m);
        let wave_force = z1 * z2 / (z1 + z2) * w;
        let mut bars = [GpuBar::default(); 2];
        for (i, wv) in waves.iter().enumerate() {
            bars[i] = GpuBar {
                origin_x: if i == 0 { -gap as f32 } else { gap as f32 },
                direction: if i == 0 { -1.0 } else { 1.0 },
                inv_stress_scale: (wv.area_m2 / wave_force) as f32,
                y_bottom: BAR_Y.0,
                y_top: BAR_Y.1,
                world_per_metre: wpm[i] as f32,
                ..GpuBar::of_waves(wv, entries[i], v_scale)
            };
        }
        BarsLayout {
            bars,
            gap,
            world_per_metre: wpm,
            to_scale,
            stress_scale_pa: wave_force / waves[0].area_m2,
            left: -extent[0] - gap * 4.0,
            right: extent[1] + gap * 4.0,
            bottom: 0.0,
            top: 1.0,
        }
    }

    /// The shader's uniforms at animation time `t`.
    pub fn uniforms(&self, t: f64) -> GpuUniforms {
        uniforms([self.left, self.right, self.bottom, self.top], t, 2)
    }

    /// A lumped result's bodies (no waves) as their uniform-stress equivalent, on the bars'
    /// geometry and colour scale: `gpu` from [`GpuHistory::uniform`].
    pub fn uniform(sc: &ImpactScenario, r: &ImpactResult, gpu: &GpuHistory) -> Self {
        let bars = [sc.bar1, sc.bar2];
        // A d'Alembert layout of the same bars gives the geometry and the colour scales.
        let stand_in: [BarWaves; 2] = std::array::from_fn(|i| BarWaves {
            body_length_m: bars[i].length_m,
            zone_length_m: 0.0,
            wave_speed_m_s: bars[i].wave_speed_m_s(),
            area_m2: bars[i].area_m2(),
            impedance_n_s_m: bars[i].impedance_n_s_m(),
            initial_velocity_m_s: bars[i].velocity_m_s,
            push_direction: if i == 0 { -1.0 } else { 1.0 },
            history: History::Uniform {
                dt_s: 1.0,
                values: vec![],
            },
            end_s: 0.0,
            decay_per_s: 0.0,
        });
        let mut layout = Self::new(&stand_in, sc.approach_velocity_m_s(), gpu);
        for (i, b) in layout.bars.iter_mut().enumerate() {
            let (offset, count, _, _) = gpu.layout[i];
            b.kind = 1;
            b.aux_offset = offset + count;
            b.inv_mass = (1.0 / r.masses_kg[i]) as f32;
            b.round_trip = 0.0;
        }
        layout
    }

    /// The same bars laid out for a space-time diagram: x as in the bar view, y from 0
    /// (`t_start`) to 1 (`t_start + t_span`).
    pub fn xt(&self) -> Self {
        let mut out = *self;
        for b in out.bars.iter_mut() {
            b.y_bottom = 0.0;
            b.y_top = 1.0;
        }
        out
    }

    /// The diagram's uniforms: the world [left, right] x [0, 1], its time axis and field.
    pub fn xt_uniforms(&self, t_start: f64, t_span: f64, field: XtShown) -> GpuUniforms {
        GpuUniforms {
            field: field as u32,
            t_start: t_start as f32,
            t_span: t_span as f32,
            ..uniforms([self.left, self.right, 0.0, 1.0], t_start, 2)
        }
    }
}

/// Uniforms for `bar_count` bars at time `t` in the world rectangle [left, right, bottom, top].
pub fn uniforms(world: [f64; 4], t: f64, bar_count: u32) -> GpuUniforms {
    let [left, right, bottom, top] = world.map(|v| v as f32);
    GpuUniforms {
        view: view(left, right, bottom, top),
        time: t as f32,
        bar_count,
        field: 0,
        t_start: 0.0,
        t_span: 0.0,
        _pad: [0.0; 3],
    }
}

/// The shader's colour map (`diverging` in field.wgsl) as linear RGB, in f32 for the GPU
/// side: [`crate::export::xt::diverging_linear`].
pub fn diverging(s: f32) -> [f32; 3] {
    crate::export::xt::diverging_linear(s as f64).map(|c| c as f32)
}

/// Orthographic view of the world rectangle [left, right] x [bottom, top].
pub fn view(left: f32, right: f32, bottom: f32, top: f32) -> [[f32; 4]; 4] {
    glam::camera::rh::proj::directx::orthographic(left, right, bottom, top, -1.0, 1.0)
        .to_cols_array_2d()
}

/// A world rectangle shown in a screen rectangle: where to paint the bars and where overlays go.
pub struct Viewport {
    pub rect: eframe::egui::Rect,
    pub left: f64,
    pub right: f64,
    pub bottom: f64,
    pub top: f64,
}

impl Viewport {
    pub fn to_screen(&self, x: f64, y: f64) -> eframe::egui::Pos2 {
        let r = self.rect;
        eframe::egui::Pos2::new(
            r.left() + ((x - self.left) / (self.right - self.left)) as f32 * r.width(),
            r.bottom() - ((y - self.bottom) / (self.top - self.bottom)) as f32 * r.height(),
        )
    }

    /// Queues the bars for the GPU as `view`, in the slot `slot` (one per view on screen).
    pub fn paint(
        &self,
        ui: &eframe::egui::Ui,
        slot: u64,
        view: View,
        uniforms: GpuUniforms,
        bars: Vec<GpuBar>,
        history: Arc<GpuHistory>,
    ) {
        ui.painter().add(egui_wgpu::Callback::new_paint_callback(
            self.rect,
            BarsCallback {
                slot,
                view,
                uniforms,
                bars,
                history,
            },
        ));
    }
}
