//! `hertz-tui merge`: shards of one map into the whole map, byte for byte the file the unsharded
//! run writes; refuses shards of different maps, a shard twice, a missing shard, a file cut short.

use super::file::{Kind, Layer, MapFile};

/// The whole map from its shards (`(file name, text)` each), and the format they share.
pub fn merge(files: &[(String, String)]) -> Result<(MapFile, Kind), String> {
    let parsed = files
        .iter()
        .map(|(name, text)| MapFile::parse(name, text).map(|(f, k)| (name.as_str(), f, k)))
        .collect::<Result<Vec<_>, _>>()?;
    let Some((first_name, first, kind)) = parsed.first() else {
        return Err("merge: no files given".into());
    };
    let count = first.shard.map_or(1, |s| s.count);
    // The layers, from a file that has cells (a shard without rows has none to name them by).
    let reference = parsed
        .iter()
        .map(|p| &p.1)
        .find(|f| !f.layers.is_empty())
        .unwrap_or(first);
    let mut owner: Vec<Option<usize>> = vec![None; count];
    for (i, (name, file, k)) in parsed.iter().enumerate() {
        if k != kind {
            return Err(format!(
                "{name}: {} while {first_name} is {}: merge shards written in one format",
                k.name(),
                kind.name()
            ));
        }
        if file.header != first.header {
            return Err(format!(
                "{name}: a different map than {first_name} ({}): shards must come from the same command with only --shard changed",
                differing(&file.header, &first.header)
            ));
        }
        let shard = file
            .shard
            .unwrap_or(crate::model::system::map::Shard::WHOLE);
        if shard.count != count {
            return Err(format!(
                "{name}: shard {}/{} while {first_name} is one of {count}: all shards must use the same N",
                shard.index, shard.count
            ));
        }
        if let Some(other) = owner[shard.index - 1].replace(i) {
            return Err(format!(
                "shard {}/{count} given twice: {} and {name}",
                shard.index, parsed[other].0
            ));
        }
        check_cells(name, file, shard, &reference.layers)?;
    }
    let missing: Vec<String> = owner
        .iter()
        .enumerate()
        .filter(|(_, o)| o.is_none())
        .map(|(i, _)| (i + 1).to_string())
        .collect();
    if !missing.is_empty() {
        return Err(format!(
            "missing shard{} {} of {count}: the merged map would have holes",
            if missing.len() > 1 { "s" } else { "" },
            missing.join(", ")
        ));
    }
    let (nx, ny) = (first.header.x.points, first.header.y.points);
    let mut layers: Vec<Layer> = reference
        .layers
        .iter()
        .map(|l| Layer {
            contact: l.contact.clone(),
            cells: Vec::with_capacity(nx * ny),
        })
        .collect();
    for iy in 0..ny {
        let holder = owner[iy % count].ok_or_else(|| format!("row {iy}: no shard holds it"))?;
        let file = &parsed[holder].1;
        for (layer, from) in layers.iter_mut().zip(&file.layers) {
            let start = from.cells.partition_point(|c| c.iy < iy);
            layer
                .cells
                .extend_from_slice(&from.cells[start..start + nx]);
        }
    }
    Ok((
        MapFile {
            header: first.header.clone(),
            shard: None,
            layers,
        },
        *kind,
    ))
}

/// Which header field differs, in words.
fn differing(a: &super::file::Header, b: &super::file::Header) -> String {
    let fields = [
        ("scene", a.scene != b.scene),
        ("--set", a.set != b.set),
        ("contact", a.contact != b.contact),
        ("x axis", a.x != b.x),
        ("y axis", a.y != b.y),
        ("run settings", a.run != b.run),
        ("model", a.model != b.model),
    ];
    let names: Vec<&str> = fields.iter().filter(|f| f.1).map(|f| f.0).collect();
    format!("{} differ", names.join(", "))
}

/// A shard holds every cell of its rows, in order, in the same layers as the first file.
fn check_cells(
    name: &str,
    file: &MapFile,
    shard: crate::model::system::map::Shard,
    layers: &[Layer],
) -> Result<(), String> {
    let (nx, ny) = (file.header.x.points, file.header.y.points);
    let names = |ls: &[Layer]| ls.iter().map(|l| l.contact.clone()).collect::<Vec<_>>();
    // A shard of more shards than rows holds no row: its CSV has no cells to name a layer by.
    let no_rows = shard.rows(ny).next().is_none();
    if no_rows && file.layers.iter().all(|l| l.cells.is_empty()) {
        return Ok(());
    }
    if names(&file.layers) != names(layers) {
        return Err(format!(
            "{name}: layers {:?}, expected {:?}",
            names(&file.layers),
            names(layers)
        ));
    }
    for layer in &file.layers {
        let mut expected = shard
            .rows(ny)
            .flat_map(|iy| (0..nx).map(move |ix| (ix, iy)));
        for cell in &layer.cells {
            match expected.next() {
                Some(at) if at == (cell.ix, cell.iy) => {}
                Some((ix, iy)) => {
                    return Err(format!(
                        "{name}: layer {}: cell ({}, {}) where ({ix}, {iy}) was expected",
                        layer.contact, cell.ix, cell.iy
                    ));
                }
                None => {
                    return Err(format!(
                        "{name}: layer {}: cell ({}, {}) is not in shard {}/{}",
                        layer.contact, cell.ix, cell.iy, shard.index, shard.count
                    ));
                }
            }
        }
        if let Some((ix, iy)) = expected.next() {
            return Err(format!(
                "{name}: layer {}: cell ({ix}, {iy}) is missing",
                layer.contact
            ));
        }
    }
    Ok(())
}
