//! Ground motion files: PEER NGA `.AT2` and plain text (time and acceleration columns, or values
//! only with a given step), the records built into the program, and the synthetic record. A
//! malformed file gives an error naming its line.

pub use crate::model::motion::Units;
use crate::model::motion::synthetic::SyntheticSpec;
use crate::model::motion::{G, GroundMotion};
use crate::model::settings::building as setting;

/// A record shipped with the program: its name, what it is, and its text (our header, then
/// time and acceleration in g).
pub struct BuiltIn {
    pub name: &'static str,
    /// How a record is named in reports.
    pub title: &'static str,
    pub about: &'static str,
    text: &'static str,
}

/// Records built into the program, usable by name wherever a motion file is asked for.
pub const BUILT_IN: &[BuiltIn] = &[BuiltIn {
    name: "elcentro-1940",
    title: "El Centro 1940 N-S (Peknold version)",
    about: "1940 El Centro (Imperial Valley) N-S, Peknold version: 1559 points at 0.02 s, PGA 0.319 g",
    text: include_str!("../../assets/motions/elcentro-1940-ns.txt"),
}];

/// Whether `name` is a built-in record's.
pub fn is_built_in(name: &str) -> bool {
    BUILT_IN.iter().any(|b| b.name == name)
}

/// A built-in record by name.
pub fn built_in(name: &str) -> Option<GroundMotion> {
    let b = BUILT_IN.iter().find(|b| b.name == name)?;
    let mut m = parse_text(b.text, b.name, Units::G, None).expect("the built-in records parse");
    m.name = format!("{} [built in: {}]", b.title, b.name);
    Some(m)
}

/// Where the ground motion comes from and how it is read.
#[derive(Debug, Clone, PartialEq)]
pub struct MotionSpec {
    /// A built-in record's name or a record file; `None` uses the synthetic record.
    pub file: Option<String>,
    pub units: Units,
    pub scale: f64,
    pub duration_s: Option<f64>,
    pub dt_s: Option<f64>,
    pub synthetic: SyntheticSpec,
    /// Seconds of rest appended to the record (a residual drift settles in them).
    pub settle_s: f64,
}

impl Default for MotionSpec {
    fn default() -> Self {
        MotionSpec {
            file: None,
            units: Units::G,
            scale: 1.0,
            duration_s: None,
            dt_s: None,
            synthetic: SyntheticSpec::default(),
            settle_s: 0.0,
        }
    }
}

/// The most samples of rest `motion.settle_s` may append (80 MB of record).
const MAX_SETTLE_SAMPLES: f64 = 1e7;

/// Reads (a built-in name or a file) or generates the record a spec asks for, truncated and
/// scaled. Errors name the source and, for a malformed file, the line.
pub fn load(spec: &MotionSpec) -> Result<GroundMotion, MotionError> {
    let mut motion = match &spec.file {
        Some(name) if is_built_in(name) => built_in(name).expect("just found"),
        Some(path) => {
            let text = super::file::read_text(std::path::Path::new(path)).map_err(|e| {
                let names: Vec<&str> = BUILT_IN.iter().map(|b| b.name).collect();
                err(
                    path,
                    None,
                    format!(
                        "{e} (built-in records: {}; synthetic or synthetic:SEED; or a .AT2 or text file)",
                        names.join(", ")
                    ),
                )
            })?;
            parse(&text, path, spec.units, spec.dt_s)?
        }
        None => spec.synthetic.generate(),
    };
    let too_short = |m: &GroundMotion| m.accel_m_s2.len() < 2;
    if too_short(&motion) {
        let why = match &spec.file {
            None => format!(
                "{}: {} s is less than two samples of {} s",
                setting::MOTION_LENGTH.key,
                crate::model::settings::shown(spec.synthetic.duration_s),
                crate::model::settings::shown(spec.synthetic.dt_s)
            ),
            Some(_) => "the record has fewer than two samples".into(),
        };
        return Err(err(&motion.name, None, why));
    }
    if let Some(d) = spec.duration_s {
        motion = motion.truncated(d);
        if too_short(&motion) {
            return Err(err(
                &motion.name,
                None,
                format!(
                    "{}: {} s leaves fewer than two samples of a record sampled every {} s",
                    setting::MOTION_DURATION.key,
                    crate::model::settings::shown(d),
                    crate::model::settings::shown(motion.dt_s)
                ),
            ));
        }
    }
    if spec.scale != 1.0 {
        motion = motion.scaled(spec.scale);
        if motion.accel_m_s2.iter().any(|a| !a.is_finite()) {
            return Err(err(
                &motion.name,
                None,
                format!(
                    "{}: {} makes the record overflow",
                    setting::MOTION_SCALE.key,
                    crate::model::settings::shown(spec.scale)
                ),
            ));
        }
    }
    if spec.settle_s > 0.0 {
        let samples = spec.settle_s / motion.dt_s;
        if samples > MAX_SETTLE_SAMPLES {
            return Err(err(
                &motion.name,
                None,
                format!(
                    "{}: {} s of rest is {} samples of {} s, more than {MAX_SETTLE_SAMPLES:e}; settle for less time",
                    setting::MOTION_SETTLE.key,
                    crate::model::settings::shown(spec.settle_s),
                    crate::model::settings::shown(samples.ceil()),
                    crate::model::settings::shown(motion.dt_s)
                ),
            ));
        }
        motion = motion.settled(spec.settle_s);
    }
    Ok(motion)
}

/// A record that could not be read: which file, which line, why.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{file}{}: {message}", super::file::at_line(*.line))]
pub struct MotionError {
    /// The file (or the record's name).
    pub file: String,
    pub line: Option<usize>,
    pub message: String,
}

/// Reads a record. `.AT2` files (by extension or by their PEER header) carry their own step and
/// are in g; other files are text in `units`, with `dt_s` required for a values-only file.
pub fn parse(
    text: &str,
    source: &str,
    units: Units,
    dt_s: Option<f64>,
) -> Result<GroundMotion, MotionError> {
    let is_at2 = source.to_ascii_lowercase().ends_with(".at2")
        || text.lines().next().is_some_and(|l| l.contains("PEER"));
    if is_at2 {
        parse_at2(text, source)
    } else {
        parse_text(text, source, units, dt_s)
    }
}

fn err(source: &str, line: Option<usize>, message: impl Into<String>) -> MotionError {
    MotionError {
        file: source.to_string(),
        line,
        message: message.into(),
    }
}

/// The value `motion.file` and `--motion` take, in one grammar everywhere: `synthetic`,
/// `synthetic:SEED` (a whole number), a built-in record's name, or a file path.
#[derive(Debug, Clone, PartialEq)]
pub enum RecordSource {
    Synthetic(Option<u64>),
    File(String),
}

impl RecordSource {
    pub fn parse(text: &str) -> Result<Self, String> {
        let t = text.trim();
        if t == "synthetic" {
            return Ok(RecordSource::Synthetic(None));
        }
        if let Some(seed) = t.strip_prefix("synthetic:") {
            let max = crate::model::settings::building::MAX_SEED;
            return seed
                .trim()
                .parse::<u64>()
                .ok()
                .filter(|&s| s <= max)
                .map(|s| RecordSource::Synthetic(Some(s)))
                .ok_or_else(|| {
                    format!(
                        "'{}': the seed must be a whole number from 0 to {max}, as in synthetic:42",
                        super::file::excerpt(seed)
                    )
                });
        }
        Ok(RecordSource::File(text.to_string()))
    }
}

impl MotionSpec {
    /// Why a `motion.*` key has no effect on this spec's record, where it has none: the
    /// synthetic record's keys beside a record file, a text file's units and step beside a
    /// record that carries its own.
    pub fn unused(&self, key: &str) -> Option<String> {
        let synthetic_only = [
            setting::MOTION_PGA.key,
            setting::MOTION_SEED.key,
            setting::MOTION_LENGTH.key,
        ];
        let text_only = [setting::MOTION_UNITS.key, setting::MOTION_DT.key];
        match &self.file {
            None if text_only.contains(&key) => Some(
                "the record is the synthetic one, which has its own step and units; this key is for a text record file"
                    .into(),
            ),
            Some(name) if synthetic_only.contains(&key) => Some(format!(
                "this key shapes the synthetic record, and the record is {name}"
            )),
            Some(name)
                if text_only.contains(&key)
                    && (is_built_in(name) || name.to_ascii_lowercase().ends_with(".at2")) =>
            {
                Some(format!(
                    "{name} carries its own step and units (g); this key is for a text record file"
                ))
            }
            _ => None,
        }
    }

    /// Points the spec at a source given as text (see [`RecordSource`]).
    pub fn set_source(&mut self, text: &str) -> Result<(), String> {
        match RecordSource::parse(text)? {
            RecordSource::Synthetic(seed) => {
                self.file = None;
                if let Some(s) = seed {
                    self.synthetic.seed = s;
                }
            }
            RecordSource::File(f) => self.file = Some(f),
        }
        Ok(())
    }
}

fn number(token: &str, source: &str, line: usize) -> Result<f64, MotionError> {
    let v: f64 = token.parse().map_err(|_| {
        err(
            source,
            Some(line),
            format!("'{}' is not a number", super::file::excerpt(token)),
        )
    })?;
    if v.is_finite() {
        Ok(v)
    } else {
        Err(err(
            source,
            Some(line),
            format!("'{}' is not a finite number", super::file::excerpt(token)),
        ))
    }
}

/// `value` in the file's units converted to m/s^2; a value that overflows there is refused by
/// its line.
fn in_m_s2(value: f64, scale: f64, source: &str, line: usize) -> Result<f64, MotionError> {
    let a = value * scale;
    if a.is_finite() {
        Ok(a)
    } else {
        Err(err(
            source,
            Some(line),
            format!("{value:e} overflows when converted to m/s^2"),
        ))
    }
}

/// PEER NGA AT2: three header lines, then `NPTS=   5372, DT=   .0100 SEC,` (or the newer
/// `5372    0.0100    NPTS, DT`), then the values in g.
pub fn parse_at2(text: &str, source: &str) -> Result<GroundMotion, MotionError> {
    let lines: Vec<&str> = text.lines().collect();
    if lines.len() < 5 {
        return Err(err(
            source,
            Some(lines.len().max(1)),
            "an AT2 file has 4 header lines and then values",
        ));
    }
    let header = lines[3];
    let (npts, dt) = if header.to_ascii_uppercase().contains("NPTS=") {
        let up = header.to_ascii_uppercase();
        let after = |key: &str| -> Option<&str> {
            let i = up.find(key)? + key.len();
            header[i..]
                .split(|c: char| c == ',' || c.is_whitespace())
                .find(|s| !s.is_empty())
        };
        let n = after("NPTS=").ok_or_else(|| err(source, Some(4), "NPTS= has no value"))?;
        let d = after("DT=").ok_or_else(|| err(source, Some(4), "DT= has no value"))?;
        (number(n, source, 4)?, number(d, source, 4)?)
    } else {
        let mut it = header.split_whitespace();
        match (it.next(), it.next()) {
            (Some(n), Some(d)) => (number(n, source, 4)?, number(d, source, 4)?),
            _ => {
                return Err(err(
                    source,
                    Some(4),
                    "expected `NPTS=..., DT=...` or `NPTS DT` on the fourth line",
                ));
            }
        }
    };
    if !(npts >= 1.0 && npts.fract() == 0.0) {
        return Err(err(
            source,
            Some(4),
            format!("NPTS = {npts} is not a positive whole number"),
        ));
    }
    if dt <= 0.0 {
        return Err(err(source, Some(4), format!("DT = {dt} must be > 0 s")));
    }
    // The header's count is checked against the values below; trusting it for the allocation
    // would let a mutated header (NPTS=1e18) abort the program.
    let mut values = Vec::with_capacity((npts as usize).min(16 * text.len() / 8 + 16));
    for (i, line) in lines.iter().enumerate().skip(4) {
        for tok in line.split_whitespace() {
            values.push(in_m_s2(number(tok, source, i + 1)?, G, source, i + 1)?);
        }
    }
    if values.len() != npts as usize {
        return Err(err(
            source,
            Some(lines.len()),
            format!(
                "the header promises NPTS = {npts} values, the file has {}",
                values.len()
            ),
        ));
    }
    Ok(GroundMotion {
        name: source.to_string(),
        dt_s: dt,
        accel_m_s2: values,
    })
}

/// Calls `f` with each field of a line: the text between commas and white space. An ASCII line
/// (any record we know of) is split byte by byte.
fn each_field(
    t: &str,
    mut f: impl FnMut(&str) -> Result<(), MotionError>,
) -> Result<(), MotionError> {
    if !t.is_ascii() {
        for s in t
            .split(|c: char| c == ',' || c.is_whitespace())
            .filter(|s| !s.is_empty())
        {
            f(s)?;
        }
        return Ok(());
    }
    // The ASCII characters char::is_whitespace takes: u8's white space and the vertical tab.
    let apart = |b: u8| b == b',' || b.is_ascii_whitespace() || b == 0x0b;
    let b = t.as_bytes();
    let mut i = 0;
    while i < b.len() {
        while i < b.len() && apart(b[i]) {
            i += 1;
        }
        let start = i;
        while i < b.len() && !apart(b[i]) {
            i += 1;
        }
        if i > start {
            f(&t[start..i])?;
        }
    }
    Ok(())
}

/// Text: `#` or `%` comments, values separated by blanks or commas. Rows of two numbers are
/// (time, acceleration) unless a step is given; anything else is a list of values at `dt_s`.
pub fn parse_text(
    text: &str,
    source: &str,
    units: Units,
    dt_s: Option<f64>,
) -> Result<GroundMotion, MotionError> {
    let scale = units.to_m_s2();
    // Every value in one column, each row its line and its range there (a vector a row took
    // most of the time reading a record).
    let mut values: Vec<f64> = Vec::with_capacity(text.len() / 8);
    let mut spans: Vec<(usize, std::ops::Range<usize>)> = Vec::new();
    for (i, line) in text.lines().enumerate() {
        let t = line.trim();
        if t.is_empty() || t.starts_with('#') || t.starts_with('%') {
            continue;
        }
        let start = values.len();
        each_field(t, |s| {
            values.push(number(s, source, i + 1)?);
            Ok(())
        })?;
        spans.push((i + 1, start..values.len()));
    }
    let rows: Vec<(usize, &[f64])> = spans
        .into_iter()
        .map(|(line, r)| (line, &values[r]))
        .collect();
    if rows.is_empty() {
        return Err(err(source, None, "no data"));
    }
    let two_columns = rows.iter().all(|(_, r)| r.len() == 2);
    for (line, r) in &rows {
        let accelerations = if two_columns && dt_s.is_none() {
            &r[1..]
        } else {
            &r[..]
        };
        for &a in accelerations {
            in_m_s2(a, scale, source, *line)?;
        }
    }
    if two_columns && dt_s.is_none() {
        let times: Vec<f64> = rows.iter().map(|(_, r)| r[0]).collect();
        if rows.len() < 2 {
            return Err(err(
                source,
                Some(rows[0].0),
                "one (time, acceleration) row gives no step",
            ));
        }
        let dt = times[1] - times[0];
        if dt <= 0.0 {
            return Err(err(
                source,
                Some(rows[1].0),
                "time must increase (or give motion.dt for a values-only file)",
            ));
        }
        for k in 1..rows.len() {
            let step = times[k] - times[k - 1];
            if (step - dt).abs() > 1e-6 * dt.max(1.0) + 1e-3 * dt {
                return Err(err(
                    source,
                    Some(rows[k].0),
                    format!(
                        "the time step changes from {dt} s to {step} s; a uniform step is needed"
                    ),
                ));
            }
        }
        if times[0].abs() > 1e-9 {
            return Err(err(
                source,
                Some(rows[0].0),
                format!(
                    "the record starts at t = {} s; it must start at 0",
                    times[0]
                ),
            ));
        }
        return Ok(GroundMotion {
            name: source.to_string(),
            dt_s: dt,
            accel_m_s2: rows.iter().map(|(_, r)| r[1] * scale).collect(),
        });
    }
    let dt = dt_s.ok_or_else(|| {
        err(
            source,
            Some(rows[0].0),
            format!(
                "{} values per row: give the step with --set motion.dt=SECONDS",
                rows[0].1.len()
            ),
        )
    })?;
    if !(dt.is_finite() && dt > 0.0) {
        return Err(err(
            source,
            None,
            format!("{} = {dt} must be > 0 s", setting::MOTION_DT.key),
        ));
    }
    Ok(GroundMotion {
        name: source.to_string(),
        dt_s: dt,
        accel_m_s2: rows
            .into_iter()
            .flat_map(|(_, r)| r)
            .map(|&a| a * scale)
            .collect(),
    })
}
