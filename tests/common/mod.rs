//! Helpers shared by the integration tests.
#![allow(dead_code)]

use pounding::model::field::BarWaves;
use pounding::model::impact::{ImpactResult, ModelKind, solve};
use pounding::model::scenario::ImpactScenario;

/// The `pounding` binary run with `args`.
pub fn pounding(args: &[&str]) -> std::process::Output {
    output_in_own_session(std::process::Command::new(env!("CARGO_BIN_EXE_pounding")).args(args))
}

/// Runs a command with its own place for the window's saved session, removed after.
pub fn output_in_own_session(command: &mut std::process::Command) -> std::process::Output {
    let saved = with_own_saved_session(command);
    let o = command.output().expect("the binary runs");
    std::fs::remove_dir_all(saved).ok();
    o
}

/// Gives a command its own, empty, place for the window's saved session (returned, for
/// removing): a window the tests open neither starts from the machine user's last session (a
/// 100-storey scene made every window test wait for its run) nor leaves its own there.
fn with_own_saved_session(command: &mut std::process::Command) -> std::path::PathBuf {
    static NEXT: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let k = NEXT.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let dir =
        std::env::temp_dir().join(format!("pounding-test-session-{}-{k}", std::process::id()));
    command.env("XDG_DATA_HOME", &dir);
    dir
}

pub fn stdout(o: &std::process::Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

pub fn stderr(o: &std::process::Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

pub fn run(model: ModelKind, sc: &ImpactScenario) -> ImpactResult {
    solve(model, sc).unwrap_or_else(|e| panic!("{} should solve: {e}", model.name()))
}

pub fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs().max(f64::MIN_POSITIVE)
}

/// Z1 Z2 / (Z1 + Z2) (v1 - v2): the wave-theory force.
pub fn wave_force(sc: &ImpactScenario) -> f64 {
    let (z1, z2) = (sc.bar1.impedance_n_s_m(), sc.bar2.impedance_n_s_m());
    z1 * z2 / (z1 + z2) * sc.approach_velocity_m_s()
}

/// Momentum of a bar computed from its velocity field (rho~ A times the integral of v dx),
/// independently of the impulse the solver reports. Simpson's rule on `n` intervals.
pub fn field_momentum(waves: &BarWaves, density: f64, t: f64, n: usize) -> f64 {
    density * waves.area_m2 * simpson(waves.length_m(), n, |x| waves.velocity_m_s(x, t))
}

/// Simpson's rule for the integral of `f` over [0, l] on `n` (even) intervals.
pub fn simpson(l: f64, n: usize, f: impl Fn(f64) -> f64) -> f64 {
    let h = l / n as f64;
    let s: f64 = (0..=n)
        .map(|k| {
            let w = if k == 0 || k == n {
                1.0
            } else if k % 2 == 1 {
                4.0
            } else {
                2.0
            };
            w * f(k as f64 * h)
        })
        .sum();
    s * h / 3.0
}

/// Mechanical energy of a bar from its field, in a frame moving at `frame_v`: the integral of
/// rho~ A (v - frame_v)^2 / 2 + A sigma^2 / (2E).
pub fn field_energy_in_frame(
    waves: &BarWaves,
    density: f64,
    youngs: f64,
    t: f64,
    n: usize,
    frame_v: f64,
) -> f64 {
    simpson(waves.length_m(), n, |x| {
        let (v, sigma) = (waves.velocity_m_s(x, t) - frame_v, waves.stress_pa(x, t));
        0.5 * density * waves.area_m2 * v * v + 0.5 * waves.area_m2 * sigma * sigma / youngs
    })
}

/// Mechanical energy of a bar from its field (lab frame).
pub fn field_energy(waves: &BarWaves, density: f64, youngs: f64, t: f64, n: usize) -> f64 {
    field_energy_in_frame(waves, density, youngs, t, n, 0.0)
}

/// A wgpu adapter (Mesa's lavapipe will do), or `None` to skip a rendering test on a machine
/// without one. Under `CI=true` a missing adapter fails instead: CI installs one.
#[cfg(feature = "gui")]
pub fn adapter_or_skip() -> Option<eframe::egui_wgpu::wgpu::Adapter> {
    use eframe::egui_wgpu::wgpu;
    let instance =
        wgpu::Instance::new(wgpu::InstanceDescriptor::new_without_display_handle_from_env());
    match pollster::block_on(instance.request_adapter(&wgpu::RequestAdapterOptions {
        power_preference: wgpu::PowerPreference::LowPower,
        ..Default::default()
    })) {
        Ok(a) => Some(a),
        Err(e) => {
            assert!(
                std::env::var_os("CI").is_none(),
                "CI needs a wgpu adapter (Mesa lavapipe): {e}"
            );
            eprintln!("skipping: no wgpu adapter ({e})");
            None
        }
    }
}

/// A PNG file's width, height, samples per pixel and 8-bit samples.
pub fn read_png(path: &std::path::Path) -> (u32, u32, usize, Vec<u8>) {
    let file =
        std::fs::File::open(path).unwrap_or_else(|e| panic!("{} should open: {e}", path.display()));
    let mut reader = png::Decoder::new(std::io::BufReader::new(file))
        .read_info()
        .expect("a PNG");
    let mut pixels = vec![0; reader.output_buffer_size().expect("a size")];
    let info = reader.next_frame(&mut pixels).expect("decodes");
    (info.width, info.height, info.color_type.samples(), pixels)
}

/// Steps the window until every background solve has landed and stayed so for five frames.
#[cfg(feature = "gui")]
pub fn settle(harness: &mut egui_kittest::Harness<'_, pounding::app::PoundingApp>, name: &str) {
    let start = std::time::Instant::now();
    let mut quiet = 0;
    while quiet < 5 {
        harness.step();
        quiet = if harness.state().is_solving() {
            0
        } else {
            quiet + 1
        };
        assert!(
            start.elapsed() < std::time::Duration::from_secs(120),
            "{name}: solves never finished"
        );
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
    harness.run_steps(3);
}

/// Answers the step's prediction through its widgets, as a student does: the first option, or
/// a number typed, then Answer.
#[cfg(feature = "gui")]
pub fn answer(
    h: &mut egui_kittest::Harness<'static, pounding::app::PoundingApp>,
    p: &pounding::lesson::Prediction,
    at: &str,
) {
    use egui_kittest::kittest::Queryable;
    match p {
        pounding::lesson::Prediction::Choice { options, .. } => {
            h.get_by_label(&options[0]).click();
        }
        pounding::lesson::Prediction::Number { .. } => {
            h.get_by_label("your answer").click();
            h.run_steps(1);
            h.get_by_label("your answer").type_text("1");
        }
    }
    h.run_steps(2);
    h.get_by_label("Answer").click();
    settle(h, &format!("{at}: answer"));
}

/// How many pixels a window snapshot may differ from its file by, in every snapshot test.
#[cfg(feature = "gui")]
pub const MAX_FAILED_PIXELS: usize = 100;

/// The seed every property test draws its cases from, so that `cargo test` runs the same cases
/// on every machine and every run (a suite that fails at random is a gamble, not a check).
pub const PROPTEST_SEED: u64 = 19_400_518;

/// A property test's configuration: `cases` cases from the fixed seed. To search further, run
/// with `POUNDING_PROPTEST_RANDOM=1` (a fresh seed each run, printed on failure and saved in the
/// test's `.proptest-regressions` file) and `PROPTEST_CASES=N` for more cases, e.g.
/// `POUNDING_PROPTEST_RANDOM=1 PROPTEST_CASES=5000 cargo test --release --test properties`.
/// `PROPTEST_RNG_SEED=S` replays seed S. Every failure found that way is committed as a
/// regression case.
pub fn proptest_config(cases: u32) -> proptest::test_runner::Config {
    use proptest::test_runner::{Config, RngSeed};
    let from_env = Config::default();
    let random = std::env::var_os("POUNDING_PROPTEST_RANDOM").is_some();
    let seed_given = std::env::var_os("PROPTEST_RNG_SEED").is_some();
    Config {
        cases: if std::env::var_os("PROPTEST_CASES").is_some() {
            from_env.cases
        } else {
            cases
        },
        rng_seed: if random || seed_given {
            from_env.rng_seed
        } else {
            RngSeed::Fixed(PROPTEST_SEED)
        },
        ..from_env
    }
}

/// A record of rest: a bridge on it moves only as its initial velocities make it.
pub fn ground_at_rest() -> pounding::model::motion::GroundMotion {
    pounding::model::motion::GroundMotion {
        name: "rest".into(),
        dt_s: 0.01,
        accel_m_s2: vec![0.0; 5],
    }
}

/// Free girders (bearings and piers of negligible stiffness) under the Sears contact, stiff
/// (1e12 N/m), undamped, thrown at `velocities` across `gaps` (N + 1 of them).
pub fn free_girders(
    velocities: Vec<f64>,
    gaps: Vec<f64>,
) -> pounding::model::bridge::BridgeScenario {
    pounding::model::bridge::BridgeScenario {
        spans: velocities.len(),
        contact: pounding::model::building::ContactModel::Sears,
        stiffness: Some(1e12),
        pier_stiffness_n_m: vec![1e-3],
        bearing_stiffness_n_m: vec![1e-3],
        span_velocity_m_s: velocities,
        joint_gaps_m: gaps,
        girder_damping: 0.0,
        damping_ratio: 0.0,
        ..pounding::model::bridge::BridgeScenario::three_span()
    }
}

/// Three free girders, the outer two thrown at the middle one at `v` and `-v` across 1 mm
/// joints (the abutments out of reach): each joint is an impact of two equal bars.
pub fn middle_girder_struck_at_both_ends(v: f64) -> pounding::model::bridge::BridgeScenario {
    free_girders(vec![v, 0.0, -v], vec![10.0, 1e-3, 1e-3, 10.0])
}

/// One free girder thrown at 1 m/s at the left abutment, 1 mm away.
pub fn girder_thrown_at_the_left_abutment() -> pounding::model::bridge::BridgeScenario {
    free_girders(vec![-1.0], vec![1e-3, 10.0])
}

/// A scratch file unique to this test process, under `folder` of the build's own scratch folder
/// (cargo clean empties it; the files stay for a failed test's reader).
pub fn scratch_file(folder: &str, name: &str, bytes: &[u8]) -> std::path::PathBuf {
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR"))
        .join(format!("{folder}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(name);
    std::fs::write(&path, bytes).unwrap();
    path
}

/// The program's message for `args`, which it must refuse as bad input (status 2).
pub fn refused(args: &[&str]) -> String {
    let o = pounding(args);
    assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stdout(&o));
    stderr(&o)
}

/// The one JSON object the program prints for `args`, which must succeed.
pub fn json(args: &[&str]) -> serde_json::Value {
    let o = pounding(args);
    assert!(o.status.success(), "{args:?}: {}", stderr(&o));
    serde_json::from_str(&stdout(&o)).expect("one JSON object")
}
