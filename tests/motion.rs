//! Ground motion: the readers, units, and the synthetic record.

use pounding::io::motion::{Units, parse};
use pounding::model::motion::G;
use pounding::model::motion::synthetic::SyntheticSpec;

const SHARED: &str = "../shared/data";

#[test]
fn el_centro_text_record_has_the_documented_peak_and_length() {
    let Ok(text) = std::fs::read_to_string(format!("{SHARED}/elcentro_1940_ns.txt")) else {
        eprintln!("skipped: {SHARED}/elcentro_1940_ns.txt is not here");
        return;
    };
    let m = parse(&text, "elcentro_1940_ns.txt", Units::G, None).unwrap();
    let s = m.stats();
    // shared/data/README.md: 1559 points at 0.02 s, PGA 0.31882 g at 2.02 s, PGV 0.361 m/s,
    // Arias 1.80 m/s.
    assert_eq!(s.points, 1559);
    assert!((m.dt_s - 0.02).abs() < 1e-12);
    assert!((s.pga_m_s2 / G - 0.31882).abs() < 1e-9 && (s.pga_time_s - 2.02).abs() < 1e-9);
    assert!((s.pgv_m_s - 0.361).abs() < 0.001, "PGV {}", s.pgv_m_s);
    assert!((s.arias_m_s - 1.80).abs() < 0.01, "Arias {}", s.arias_m_s);
}

#[test]
fn response_spectrum_of_a_sine_peaks_at_resonance_with_the_closed_form_value() {
    // a_g = A sin(W t) for 60 s: a 5%-damped oscillator at resonance settles at
    // u = A / (2 z W^2), so its pseudo-acceleration is A / (2 z) = 10 A.
    let (amp, period) = (1.0, 0.5);
    let wf = 2.0 * std::f64::consts::PI / period;
    let dt = 0.01;
    let m = pounding::model::motion::GroundMotion {
        name: "sine".into(),
        dt_s: dt,
        accel_m_s2: (0..=6000)
            .map(|i| amp * (wf * i as f64 * dt).sin())
            .collect(),
    };
    let sa = m.spectral_accel(period, 0.05);
    assert!((sa - 10.0 * amp).abs() < 0.02 * 10.0 * amp, "Sa = {sa}");
    assert!(m.spectral_accel(0.25, 0.05) < 0.5 * sa && m.spectral_accel(1.0, 0.05) < 0.5 * sa);
}

#[test]
fn peer_at2_record_reads_with_its_own_step() {
    let Ok(text) = std::fs::read_to_string(format!("{SHARED}/RSN6_IMPVALL.I_I-ELC180-hor1.AT2"))
    else {
        eprintln!("skipped: the AT2 record is not here");
        return;
    };
    let m = parse(&text, "RSN6.AT2", Units::MetresPerSecond2, None).unwrap();
    let s = m.stats();
    // README: NPTS = 5372, DT = 0.01 s, PGA 0.2808 g at 2.18 s (AT2 files are in g whatever the
    // units asked for text).
    assert_eq!(s.points, 5372);
    assert!((m.dt_s - 0.01).abs() < 1e-12);
    assert!(
        (s.pga_m_s2 / G - 0.2808).abs() < 1e-4 && (s.pga_time_s - 2.18).abs() < 1e-9,
        "{s:?}"
    );
}

#[test]
fn both_at2_header_styles_read_the_same() {
    let values = "   .1000000E-01   .2000000E-01  -.3000000E-01\n   .4000000E-01\n";
    let old = format!(
        "PEER NGA STRONG MOTION DATABASE RECORD\nevent\nACCELERATION TIME SERIES IN UNITS OF G\nNPTS=      4, DT=   .0100 SEC,\n{values}"
    );
    let new = format!(
        "PEER NGA STRONG MOTION DATABASE RECORD\nevent\nACCELERATION TIME SERIES IN UNITS OF G\n4    0.0100    NPTS, DT\n{values}"
    );
    let (a, b) = (
        parse(&old, "a.AT2", Units::G, None).unwrap(),
        parse(&new, "b.AT2", Units::G, None).unwrap(),
    );
    assert_eq!(a.accel_m_s2, b.accel_m_s2);
    assert!((a.accel_m_s2[2] + 0.03 * G).abs() < 1e-12);
}

#[test]
fn malformed_files_name_the_line() {
    let bad_value = "PEER\nx\ny\nNPTS=   3, DT= .01 SEC,\n .1 .2\n .3x\n";
    let e = parse(bad_value, "bad.AT2", Units::G, None)
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("bad.AT2") && e.contains("line 6") && e.contains(".3x"),
        "{e}"
    );
    let short = "PEER\nx\ny\nNPTS=   4, DT= .01 SEC,\n .1 .2 .3\n";
    assert!(
        parse(short, "short.AT2", Units::G, None)
            .unwrap_err()
            .to_string()
            .contains("NPTS = 4")
    );
    let uneven = "# t a\n0.0 0.1\n0.01 0.2\n0.03 0.3\n";
    let e = parse(uneven, "uneven.txt", Units::G, None)
        .unwrap_err()
        .to_string();
    assert!(e.contains("line 4") && e.contains("time step"), "{e}");
    let one_column = "0.1\n0.2\n0.3\n";
    assert!(
        parse(one_column, "v.txt", Units::G, None)
            .unwrap_err()
            .to_string()
            .contains("motion.dt")
    );
}

#[test]
fn units_convert_to_si() {
    let text = "0.1\n0.2\n";
    for (units, factor) in [
        (Units::G, G),
        (Units::MetresPerSecond2, 1.0),
        (Units::CentimetresPerSecond2, 0.01),
    ] {
        let m = parse(text, "v.txt", units, Some(0.01)).unwrap();
        assert!((m.accel_m_s2[1] - 0.2 * factor).abs() < 1e-12);
    }
    let two = "0 1.0\n0.005 -2.0\n";
    let m = parse(two, "t.txt", Units::CentimetresPerSecond2, None).unwrap();
    assert_eq!(m.dt_s, 0.005);
    assert!((m.accel_m_s2[1] + 0.02).abs() < 1e-15);
}

#[test]
fn synthetic_record_is_reproducible_and_scaled_to_its_peak() {
    let spec = SyntheticSpec::default();
    let (a, b) = (spec.generate(), spec.generate());
    assert_eq!(a.accel_m_s2, b.accel_m_s2, "same seed, same record");
    let s = a.stats();
    assert!((s.pga_m_s2 - 0.3 * G).abs() < 1e-9);
    assert!((s.duration_s - 20.0).abs() < 1e-9);
    let other = SyntheticSpec { seed: 7, ..spec }.generate();
    assert_ne!(a.accel_m_s2, other.accel_m_s2);
    // The strong phase dominates: most of the Arias intensity arrives between 2 and 8 s.
    assert!(
        s.significant_duration_s > 4.0 && s.significant_duration_s < 12.0,
        "{s:?}"
    );
    // Filtered by soil at 2.5 Hz: the 5%-damped response spectrum peaks near 0.4 s.
    assert!(
        s.predominant_period_s > 0.2 && s.predominant_period_s < 0.6,
        "{s:?}"
    );
}
