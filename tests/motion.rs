//! Ground motion: the readers, units, and the synthetic record.

use pounding::io::motion::{MotionSpec, Units, built_in, load, parse};
use pounding::model::motion::G;
use pounding::model::motion::synthetic::SyntheticSpec;

#[test]
fn el_centro_text_record_has_the_documented_peak_and_length() {
    let text = std::fs::read_to_string("assets/motions/elcentro-1940-ns.txt").unwrap();
    let m = parse(&text, "elcentro-1940-ns.txt", Units::G, None).unwrap();
    assert_eq!(built_in("elcentro-1940").unwrap().accel_m_s2, m.accel_m_s2);
    let s = m.stats();
    // The record's header: 1559 points at 0.02 s, PGA 0.31882 g at 2.02 s; its PGV (0.361 m/s)
    // and Arias intensity (1.80 m/s) as computed independently when it was shipped.
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

/// A value as PEER writes it: mantissa in [0.1, 1) without the leading zero, `-.9984852E-03`.
fn peer_number(v: f64) -> String {
    if v == 0.0 {
        return ".0000000E+00".into();
    }
    let mut exp = v.abs().log10().floor() as i32 + 1;
    let mut digits = (v.abs() / 10f64.powi(exp) * 1e7).round() as u64;
    if digits >= 10_000_000 {
        digits /= 10;
        exp += 1;
    }
    let sign = if v < 0.0 { "-" } else { "" };
    format!("{sign}.{digits:07}E{exp:+03}")
}

/// A PEER-style AT2 file of `values` (in g) at `dt`: five values a row, the last row short.
fn at2_text(values: &[f64], dt: f64) -> String {
    let mut text = format!(
        "PEER NGA STRONG MOTION DATABASE RECORD\nTest event, 1/1/2000, Test station, 000\nACCELERATION TIME SERIES IN UNITS OF G\nNPTS=  {:5}, DT=   {} SEC,\n",
        values.len(),
        format!("{dt:.4}").trim_start_matches('0')
    );
    for row in values.chunks(5) {
        for v in row {
            text += &format!("  {:>13}", peer_number(*v));
        }
        text += "\n";
    }
    text
}

#[test]
fn peer_at2_record_reads_with_its_own_step() {
    // A record written here in PEER's layout (the NGA files are not ours to ship), read from a
    // file by extension, in g whatever the units asked for text.
    let values: Vec<f64> = (0..23)
        .map(|i| 0.25 * (0.7 * i as f64).sin() * if i == 17 { 1.2 } else { 1.0 })
        .collect();
    let path = std::env::temp_dir().join(format!("pounding-{}-test.AT2", std::process::id()));
    std::fs::write(&path, at2_text(&values, 0.005)).unwrap();
    let spec = MotionSpec {
        file: Some(path.display().to_string()),
        units: Units::MetresPerSecond2,
        ..MotionSpec::default()
    };
    let m = load(&spec).unwrap();
    std::fs::remove_file(&path).ok();
    assert_eq!(m.accel_m_s2.len(), 23);
    assert!((m.dt_s - 0.005).abs() < 1e-15);
    for (got, want) in m.accel_m_s2.iter().zip(&values) {
        assert!((got / G - want).abs() < 1e-7, "{got} against {want} g");
    }
    let s = m.stats();
    let (i, peak) = values
        .iter()
        .enumerate()
        .max_by(|a, b| a.1.abs().total_cmp(&b.1.abs()))
        .unwrap();
    assert!((s.pga_m_s2 / G - peak.abs()).abs() < 1e-7);
    assert!((s.pga_time_s - 0.005 * i as f64).abs() < 1e-12);
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
