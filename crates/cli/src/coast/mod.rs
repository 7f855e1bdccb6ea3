//! `vorrt coast`: a coastline file (`GeoJSON`, `TopoJSON`, ESRI shapefile) into
//! the small land `GeoJSON` a scenario's `land_geojson` names: clipped to a
//! box and simplified in metres (`vorrt_scenarios::coastline`; decision 38).

mod read;

pub(crate) use read::read_land;

use crate::console;
use crate::error::{CliError, ExitStatus};
use clap::Args;
use std::path::{Path, PathBuf};
use vorrt_scenarios::coastline::{
    BoundingBox, Coast, CoastOptions, DEFAULT_TOLERANCE_M, prepare_coast, to_geojson_string,
};

/// The margin `vorrt import-ais --coast` keeps around the scenario's
/// vessels and goal when it clips the coast, nautical miles: room for the
/// alterations a planner considers, and for land just out of sight.
pub(crate) const DEFAULT_COAST_MARGIN_NM: f64 = 5.0;

/// The file name `vorrt import-ais --coast` writes the land to, beside the
/// scenario.
pub(crate) const LAND_FILE: &str = "land.geojson";

/// `vorrt coast`.
#[derive(Debug, Clone, Args)]
#[expect(
    clippy::doc_markdown,
    reason = "clap help text, printed verbatim by --help"
)]
pub(crate) struct CoastArgs {
    /// The coastline: .geojson/.json (GeoJSON or TopoJSON, e.g. Natural
    /// Earth's land-10m.json), .topojson, or .shp (ESRI shapefile, e.g. GSHHS
    /// L1).
    pub(crate) input: PathBuf,
    /// The area to keep, degrees: WEST,SOUTH,EAST,NORTH (e.g. 1.0,50.8,2.0,51.3).
    #[arg(long, value_name = "W,S,E,N", allow_hyphen_values = true)]
    pub(crate) bbox: String,
    /// The land GeoJSON to write.
    #[arg(long, value_name = "LAND.geojson")]
    pub(crate) out: PathBuf,
    /// Simplification tolerance, metres (Douglas-Peucker in a local metric
    /// frame; 0 keeps every vertex).
    #[arg(long, value_name = "M", default_value_t = DEFAULT_TOLERANCE_M)]
    pub(crate) tolerance_m: f64,
    /// Drop polygons and holes smaller than this, square metres
    /// [default: the tolerance squared].
    #[arg(long, value_name = "M2")]
    pub(crate) min_area_m2: Option<f64>,
    /// The TopoJSON object to read [default: land when there is one, else all].
    #[arg(long, value_name = "NAME")]
    pub(crate) layer: Option<String>,
    /// A provenance and licence line written into the output's vorrt.note.
    #[arg(long, value_name = "TEXT")]
    pub(crate) note: Option<String>,
}

/// Runs `vorrt coast`.
///
/// # Errors
/// [`CliError::BadInput`] when the input cannot be read or an option is
/// wrong; [`CliError::Output`] when the output cannot be written.
pub(crate) fn coast_command(args: &CoastArgs) -> Result<ExitStatus, CliError> {
    let bbox = BoundingBox::parse(&args.bbox)
        .map_err(|error| CliError::BadInput(format!("--bbox: {error}")))?;
    let mut options = CoastOptions::new(bbox, args.tolerance_m);
    if let Some(min_area_m2) = args.min_area_m2 {
        options.min_area_m2 = min_area_m2;
    }
    let coast = clip_file(&args.input, args.layer.as_deref(), &options)?;
    let source = args.input.file_name().map_or_else(
        || args.input.display().to_string(),
        |name| name.to_string_lossy().into_owned(),
    );
    write_coast(&coast, &args.out, &source, &options, args.note.as_deref())?;
    Ok(ExitStatus::Success)
}

/// Reads `input` and prepares its coast for `options`, warning on stderr
/// when no land is left in the box.
///
/// # Errors
/// [`CliError::BadInput`] when the file cannot be read or an option is wrong.
pub(crate) fn clip_file(
    input: &Path,
    layer: Option<&str>,
    options: &CoastOptions,
) -> Result<Coast, CliError> {
    let land = read_land(input, layer, Some(&options.bbox))?;
    let coast =
        prepare_coast(&land, options).map_err(|error| CliError::BadInput(error.to_string()))?;
    if coast.land_lon_lat.0.is_empty() {
        console::warn(&format!(
            "warning: {}: no land left in the box {},{},{},{} (open water, or the wrong box?)",
            input.display(),
            options.bbox.west_deg,
            options.bbox.south_deg,
            options.bbox.east_deg,
            options.bbox.north_deg
        ));
    }
    Ok(coast)
}

/// Writes `coast` as `GeoJSON` to `out` (creating its folder) and prints what
/// each stage kept.
///
/// # Errors
/// [`CliError::Output`] when the file cannot be written.
pub(crate) fn write_coast(
    coast: &Coast,
    out: &Path,
    source: &str,
    options: &CoastOptions,
    note: Option<&str>,
) -> Result<(), CliError> {
    let bbox = &options.bbox;
    let mut properties = serde_json::json!({
        "generator": "vorrt coast",
        "source": source,
        "bbox": [bbox.west_deg, bbox.south_deg, bbox.east_deg, bbox.north_deg],
        "tolerance_m": options.tolerance_m,
        "min_area_m2": options.min_area_m2,
    });
    if let Some(note) = note {
        properties["note"] = serde_json::Value::String(note.to_owned());
    }
    let text = to_geojson_string(&coast.land_lon_lat, &properties);
    if let Some(parent) = out.parent().filter(|parent| !parent.as_os_str().is_empty()) {
        std::fs::create_dir_all(parent).map_err(|error| {
            CliError::Output(format!("cannot create {}: {error}", parent.display()))
        })?;
    }
    std::fs::write(out, text)
        .map_err(|error| CliError::Output(format!("cannot write {}: {error}", out.display())))?;
    let stats = &coast.stats;
    let simplify = &stats.simplify;
    console::line(&format!(
        "wrote {}: {} polygons, {} vertices (read {} polygons, {} vertices; {} polygons, {} vertices in the box; tolerance {} m: {} slivers and {} holes under {} m2 dropped, {} polygons simplified finer to stay valid, {} kept as they were{})",
        out.display(),
        stats.polygons_out,
        stats.vertices_out,
        stats.polygons_in,
        stats.vertices_in,
        stats.polygons_clipped,
        stats.vertices_clipped,
        options.tolerance_m,
        simplify.slivers_dropped,
        simplify.holes_dropped,
        options.min_area_m2,
        simplify.tolerance_reduced,
        simplify.kept_unsimplified,
        if simplify.merged_overlaps {
            "; overlapping polygons merged"
        } else {
            ""
        }
    ));
    Ok(())
}

/// For `vorrt import-ais --coast`: clips `coast` to the area of `scenario`'s
/// vessels and goal grown by `margin_nm`, writes it as [`LAND_FILE`] beside
/// `scenario_out`, and returns its file name, for the scenario's
/// `land_geojson` (relative: resolved from the scenario file's folder).
///
/// # Errors
/// [`CliError::BadInput`] when the coast cannot be read or the area is
/// refused; [`CliError::Output`] when the land cannot be written.
#[expect(clippy::similar_names, reason = "the same margin in two units")]
pub(crate) fn add_land(
    scenario: &vorrt_scenarios::Scenario,
    coast: &Path,
    margin_nm: f64,
    scenario_out: &Path,
) -> Result<&'static str, CliError> {
    let points: Vec<(f64, f64)> = std::iter::once(&scenario.ownship)
        .chain(&scenario.targets)
        .flat_map(|vessel| [vessel.start_lat_lon, vessel.goal_lat_lon])
        .flatten()
        .collect();
    let margin_m = margin_nm * vorrt_scenarios::geometry::units::NAUTICAL_MILE_M;
    let bbox = BoundingBox::around(&points, margin_m)
        .map_err(|error| CliError::BadInput(format!("--coast: {error}")))?;
    let options = CoastOptions::new(bbox, DEFAULT_TOLERANCE_M);
    let land = clip_file(coast, None, &options)?;
    let land_out = scenario_out
        .parent()
        .map_or_else(|| PathBuf::from(LAND_FILE), |parent| parent.join(LAND_FILE));
    let source = coast.file_name().map_or_else(
        || coast.display().to_string(),
        |name| name.to_string_lossy().into_owned(),
    );
    write_coast(&land, &land_out, &source, &options, None)?;
    Ok(LAND_FILE)
}
