//! The map file: what a map is (its header), which part of it a file holds (its shard), its cells
//! layer by layer, and a checksum; written and read as CSV or JSON (docs/maps.md §3).
//!
//! The checksum is FNV-1a (64 bits) of the CSV text above the checksum line, whatever the file's
//! format: a JSON file's is computed on the CSV rendering of the same content. It tells a file
//! cut short or edited from a whole one; the header's `model` is a hash of the system, the stops
//! and the run, so that shards of different maps never merge.

use std::fmt::Write as _;

use serde::{Deserialize, Serialize};

use crate::format::csv;
use crate::model::system::map::Shard;

/// First line of every map file.
pub const MAGIC: &str = "hertz-tui map 1";

/// The CSV columns of the cells.
pub const COLUMNS: &str = "contact,ix,iy,x,y,motion,impacts,periods,lyapunov,error";

/// One axis as written.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct AxisSpec {
    pub key: String,
    pub from: f64,
    pub to: f64,
    pub points: usize,
}

/// What the map is: equal in every shard of one map.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Header {
    pub scene: String,
    /// The `--set` overrides, space-separated.
    pub set: String,
    pub contact: String,
    pub x: AxisSpec,
    pub y: AxisSpec,
    /// The run's settings, as `key=value` words.
    pub run: String,
    /// FNV-1a of the system model, stops and run, in hex.
    pub model: String,
}

/// One cell as written.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Row {
    pub ix: usize,
    pub iy: usize,
    pub x: f64,
    pub y: f64,
    /// A motion's name, or for the difference layer `same`, `differs`, `unknown`.
    pub motion: String,
    pub impacts: Option<u32>,
    pub periods: Option<u32>,
    pub lyapunov: Option<f64>,
    pub error: Option<String>,
}

/// One stop's map (or the difference map), cells row after row.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Layer {
    pub contact: String,
    pub cells: Vec<Row>,
}

/// A map file's content.
#[derive(Debug, Clone, PartialEq)]
pub struct MapFile {
    pub header: Header,
    /// `None`: the whole map.
    pub shard: Option<Shard>,
    pub layers: Vec<Layer>,
}

/// FNV-1a, 64 bits.
pub fn fnv1a(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xcbf2_9ce4_8422_2325, |h, &b| {
        (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3)
    })
}

fn opt<T: std::fmt::Display>(v: &Option<T>) -> String {
    v.as_ref().map_or_else(String::new, T::to_string)
}

impl MapFile {
    /// The CSV text above the checksum line.
    fn csv_body(&self) -> String {
        let h = &self.header;
        let axis = |a: &AxisSpec| format!("{} {} {} {}", a.key, a.from, a.to, a.points);
        let mut s = format!("# {MAGIC}\n");
        let _ = writeln!(s, "# scene: {}", h.scene);
        let _ = writeln!(s, "# set: {}", h.set);
        let _ = writeln!(s, "# contact: {}", h.contact);
        let _ = writeln!(s, "# x: {}", axis(&h.x));
        let _ = writeln!(s, "# y: {}", axis(&h.y));
        let _ = writeln!(s, "# run: {}", h.run);
        let _ = writeln!(s, "# model: {}", h.model);
        if let Some(shard) = self.shard {
            let _ = writeln!(s, "# shard: {}/{}", shard.index, shard.count);
        }
        let _ = writeln!(s, "{COLUMNS}");
        for layer in &self.layers {
            let contact = csv::field(&layer.contact);
            for c in &layer.cells {
                let _ = writeln!(
                    s,
                    "{contact},{},{},{},{},{},{},{},{},{}",
                    c.ix,
                    c.iy,
                    c.x,
                    c.y,
                    c.motion,
                    opt(&c.impacts),
                    opt(&c.periods),
                    opt(&c.lyapunov),
                    csv::field(c.error.as_deref().unwrap_or(""))
                );
            }
        }
        s
    }

    /// The checksum of the content, hex.
    pub fn checksum(&self) -> String {
        format!("{:016x}", fnv1a(self.csv_body().as_bytes()))
    }

    /// The CSV file.
    pub fn to_csv(&self) -> String {
        let mut s = self.csv_body();
        let _ = writeln!(s, "# checksum: {}", self.checksum());
        s
    }

    /// The JSON file.
    pub fn to_json(&self) -> Result<String, serde_json::Error> {
        let json = JsonMap {
            format: MAGIC.to_string(),
            header: self.header.clone(),
            shard: self.shard.map(|s| format!("{}/{}", s.index, s.count)),
            layers: self.layers.clone(),
            checksum: self.checksum(),
        };
        let mut text = serde_json::to_string_pretty(&json)?;
        text.push('\n');
        Ok(text)
    }

    /// Reads a map file (CSV or JSON, told by its first character); `name` is used in errors.
    /// Refuses a file whose checksum is missing (a shard that did not finish) or wrong.
    pub fn parse(name: &str, text: &str) -> Result<(MapFile, Kind), String> {
        let (file, checksum, kind) = if text.trim_start().starts_with('{') {
            let json: JsonMap =
                serde_json::from_str(text).map_err(|e| format!("{name}: not a map file: {e}"))?;
            if json.format != MAGIC {
                return Err(format!(
                    "{name}: format `{}`, expected `{MAGIC}`",
                    json.format
                ));
            }
            let shard = json
                .shard
                .as_deref()
                .map(|s| parse_shard(name, 0, s))
                .transpose()?;
            let file = MapFile {
                header: json.header,
                shard,
                layers: json.layers,
            };
            (file, Some(json.checksum), Kind::Json)
        } else {
            let (file, checksum) = parse_csv(name, text)?;
            (file, checksum, Kind::Csv)
        };
        let Some(checksum) = checksum else {
            return Err(format!(
                "{name}: no checksum line: the file is incomplete (did its run finish?)"
            ));
        };
        if checksum != file.checksum() {
            return Err(format!(
                "{name}: checksum {checksum} does not match the content ({}): the file was cut short or edited",
                file.checksum()
            ));
        }
        Ok((file, kind))
    }
}

/// The format a map file was read from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    Csv,
    Json,
}

impl Kind {
    /// "a CSV file" or "a JSON file", for messages.
    pub fn name(self) -> &'static str {
        match self {
            Kind::Csv => "a CSV file",
            Kind::Json => "a JSON file",
        }
    }
}

#[derive(Serialize, Deserialize)]
struct JsonMap {
    format: String,
    header: Header,
    shard: Option<String>,
    layers: Vec<Layer>,
    checksum: String,
}

fn parse_shard(name: &str, line: usize, s: &str) -> Result<Shard, String> {
    let bad = || format!("{name}:{line}: `shard: {s}` is not I/N with 1 ≤ I ≤ N");
    let (i, n) = s.split_once('/').ok_or_else(bad)?;
    Shard::new(i.parse().map_err(|_| bad())?, n.parse().map_err(|_| bad())?).ok_or_else(bad)
}

fn parse_axis(name: &str, line: usize, s: &str) -> Result<AxisSpec, String> {
    let bad = || format!("{name}:{line}: axis `{s}` is not `KEY FROM TO POINTS`");
    let w: Vec<&str> = s.split_whitespace().collect();
    let [key, from, to, points] = w[..] else {
        return Err(bad());
    };
    Ok(AxisSpec {
        key: key.to_string(),
        from: from.parse().map_err(|_| bad())?,
        to: to.parse().map_err(|_| bad())?,
        points: points.parse().map_err(|_| bad())?,
    })
}

/// Splits a CSV line into fields (quoted fields with doubled quotes, as `csv::field` writes).
fn fields(line: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut field = String::new();
    let mut quoted = false;
    let mut chars = line.chars().peekable();
    while let Some(c) = chars.next() {
        match (c, quoted) {
            ('"', true) if chars.peek() == Some(&'"') => {
                field.push('"');
                chars.next();
            }
            ('"', _) => quoted = !quoted,
            (',', false) => out.push(std::mem::take(&mut field)),
            _ => field.push(c),
        }
    }
    out.push(field);
    out
}

fn parse_csv(name: &str, text: &str) -> Result<(MapFile, Option<String>), String> {
    let mut lines = text.lines().enumerate().map(|(i, l)| (i + 1, l));
    match lines.next() {
        Some((_, l)) if l == format!("# {MAGIC}") => {}
        _ => return Err(format!("{name}:1: not a map file (expected `# {MAGIC}`)")),
    }
    let mut meta: Vec<(usize, String, String)> = Vec::new();
    for (n, line) in lines.by_ref() {
        if line == COLUMNS {
            break;
        }
        let Some((key, value)) = line.strip_prefix("# ").and_then(|l| l.split_once(": ")) else {
            return Err(format!(
                "{name}:{n}: expected `# key: value` or the column line"
            ));
        };
        meta.push((n, key.to_string(), value.to_string()));
    }
    let get = |key: &str| {
        meta.iter()
            .find(|(_, k, _)| k == key)
            .map(|(n, _, v)| (*n, v.clone()))
            .ok_or_else(|| format!("{name}: the header has no `{key}` line"))
    };
    let (xl, x) = get("x")?;
    let (yl, y) = get("y")?;
    let header = Header {
        scene: get("scene")?.1,
        set: get("set")?.1,
        contact: get("contact")?.1,
        x: parse_axis(name, xl, &x)?,
        y: parse_axis(name, yl, &y)?,
        run: get("run")?.1,
        model: get("model")?.1,
    };
    let shard = match get("shard") {
        Ok((n, s)) => Some(parse_shard(name, n, &s)?),
        Err(_) => None,
    };
    let mut layers: Vec<Layer> = Vec::new();
    let mut checksum = None;
    for (n, line) in lines {
        if let Some(sum) = line.strip_prefix("# checksum: ") {
            checksum = Some(sum.to_string());
            break;
        }
        let f = fields(line);
        let bad = |what: &str| format!("{name}:{n}: {what} in `{line}`");
        if f.len() != 10 {
            return Err(bad("expected 10 fields"));
        }
        let number = |i: usize, what: &str| -> Result<f64, String> {
            f[i].parse()
                .map_err(|_| bad(&format!("{what} is not a number")))
        };
        let count = |i: usize, what: &str| -> Result<Option<u32>, String> {
            if f[i].is_empty() {
                return Ok(None);
            }
            f[i].parse()
                .map(Some)
                .map_err(|_| bad(&format!("{what} is not a count")))
        };
        let row = Row {
            ix: f[1].parse().map_err(|_| bad("ix is not an index"))?,
            iy: f[2].parse().map_err(|_| bad("iy is not an index"))?,
            x: number(3, "x")?,
            y: number(4, "y")?,
            motion: f[5].clone(),
            impacts: count(6, "impacts")?,
            periods: count(7, "periods")?,
            lyapunov: if f[8].is_empty() {
                None
            } else {
                Some(number(8, "lyapunov")?)
            },
            error: (!f[9].is_empty()).then(|| f[9].clone()),
        };
        match layers.last_mut() {
            Some(layer) if layer.contact == f[0] => layer.cells.push(row),
            _ => layers.push(Layer {
                contact: f[0].clone(),
                cells: vec![row],
            }),
        }
    }
    Ok((
        MapFile {
            header,
            shard,
            layers,
        },
        checksum,
    ))
}
