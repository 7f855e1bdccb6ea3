//! `vorrt import-ais`: an AIS log into a geographic scenario file (the
//! reading and the state estimates are `vorrt-ais`'s; this is the file I/O
//! and the messages).

use crate::console;
use crate::error::{CliError, ExitStatus};
use clap::Args;
use std::path::PathBuf;
use vorrt_ais::{
    DEFAULT_RANGE_NM, ImportOptions, LineCounts, ReplayOptions, build_replay, build_scenario,
    read_log,
};

/// `vorrt import-ais`.
#[derive(Debug, Clone, Args)]
#[expect(
    clippy::doc_markdown,
    reason = "clap help text, printed verbatim by --help"
)]
pub(crate) struct ImportAisArgs {
    /// The AIS log: NMEA 0183 !AIVDM/!AIVDO sentences, optionally behind
    /// NMEA 4.0 tag blocks (\c:UNIXTIME,...*hh\) that give the times.
    pub(crate) log: PathBuf,
    /// Ownship's MMSI.
    #[arg(long, value_name = "MMSI")]
    pub(crate) ownship: u32,
    /// Ownship's goal, degrees: LAT,LON (e.g. 50.3,-0.8) [required without
    /// --replay; with it, default: ownship's last recorded position].
    #[arg(
        long,
        value_name = "LAT,LON",
        allow_hyphen_values = true,
        required_unless_present = "replay"
    )]
    pub(crate) goal: Option<String>,
    /// Write a replay: every other vessel follows its recorded track (in
    /// SCENARIO.tracks.csv beside the scenario), ownship starts from its
    /// recorded state at the start [default start: when every vessel has
    /// been seen]. `vorrt simulate` sails vorrt among them; `vorrt judge
    /// SCENARIO.tracks.csv --scenario SCENARIO.ron` judges the human.
    #[arg(long)]
    pub(crate) replay: bool,
    /// The scenario file to write (RON).
    #[arg(long, value_name = "SCENARIO.ron")]
    pub(crate) out: PathBuf,
    /// The time of the scenario's start: ISO 8601 UTC (2024-05-01T12:00:00Z)
    /// or UNIX seconds [default: the log's last tag-block time].
    #[arg(long, value_name = "TIME")]
    pub(crate) at: Option<String>,
    /// Leave out vessels farther than this from ownship, nautical miles.
    #[arg(long, value_name = "R", default_value_t = DEFAULT_RANGE_NM)]
    pub(crate) range_nm: f64,
    /// A coastline (any file vorrt coast reads): clipped to the scenario's
    /// area and written as land.geojson beside the scenario, which names it
    /// in land_geojson.
    #[arg(long, value_name = "FILE")]
    pub(crate) coast: Option<PathBuf>,
    /// The margin kept around the vessels and the goal when clipping
    /// --coast, nautical miles.
    #[arg(long, value_name = "NM", default_value_t = crate::coast::DEFAULT_COAST_MARGIN_NM)]
    pub(crate) coast_margin_nm: f64,
}

/// The tracks file of the replay scenario `out`: `<stem>.tracks.csv`,
/// beside it.
fn tracks_file_name(out: &std::path::Path) -> String {
    let stem = out
        .file_stem()
        .map_or_else(|| "replay".into(), |stem| stem.to_string_lossy());
    format!("{stem}.tracks.csv")
}

fn parse_goal(text: &str) -> Result<(f64, f64), CliError> {
    let bad = || {
        CliError::BadInput(format!(
            "--goal is {text:?}, expected LAT,LON in degrees (e.g. 50.3,-0.8)"
        ))
    };
    let (lat, lon) = text.split_once(',').ok_or_else(bad)?;
    Ok((
        lat.trim().parse().map_err(|_| bad())?,
        lon.trim().parse().map_err(|_| bad())?,
    ))
}

fn parse_time(text: &str) -> Result<f64, CliError> {
    if let Ok(unix_s) = text.parse::<f64>()
        && unix_s.is_finite()
    {
        return Ok(unix_s);
    }
    let time = vorrt_scenarios::geo::parse_utc_time(text)
        .map_err(|problem| CliError::BadInput(format!("--at {problem}")))?;
    #[allow(clippy::cast_precision_loss)]
    Ok(time.unix_timestamp_nanos() as f64 / 1e9)
}

fn describe_counts(counts: &LineCounts) -> String {
    format!(
        "{} lines: {} messages used, {} skipped ({} malformed, {} bad checksums, {} of unused types), {} reports without a position, {} fragments left incomplete",
        counts.lines,
        counts.messages,
        counts.skipped(),
        counts.malformed,
        counts.bad_checksum,
        counts.unsupported_type,
        counts.no_position,
        counts.fragments
    )
}

/// Runs `vorrt import-ais`.
///
/// # Errors
/// [`CliError::BadInput`] when the log cannot be read, an option is wrong,
/// ownship is not in the log or has no position; [`CliError::Output`] when
/// the scenario cannot be written.
pub(crate) fn import_ais_command(args: &ImportAisArgs) -> Result<ExitStatus, CliError> {
    let goal_lat_lon = args.goal.as_deref().map(parse_goal).transpose()?;
    let at_unix_s = args.at.as_deref().map(parse_time).transpose()?;
    let bytes = std::fs::read(&args.log).map_err(|error| {
        CliError::BadInput(format!("cannot read {}: {error}", args.log.display()))
    })?;
    let text = String::from_utf8_lossy(&bytes);
    let log = read_log(&text);
    console::warn(&format!(
        "{}: {}",
        args.log.display(),
        describe_counts(&log.counts)
    ));
    let log_name = args.log.display().to_string();
    let (mut scenario, notes, tracks) = if args.replay {
        let tracks_file = tracks_file_name(&args.out);
        let replay = build_replay(
            &log,
            &ReplayOptions {
                log_name,
                ownship_mmsi: args.ownship,
                goal_lat_lon,
                at_unix_s,
                range_nm: args.range_nm,
                tracks_file: tracks_file.clone(),
            },
        )
        .map_err(|error| CliError::BadInput(error.to_string()))?;
        (
            replay.scenario,
            replay.notes,
            Some((args.out.with_file_name(tracks_file), replay.tracks_csv)),
        )
    } else {
        let options = ImportOptions {
            log_name,
            ownship_mmsi: args.ownship,
            // Clap requires --goal without --replay.
            goal_lat_lon: goal_lat_lon.unwrap_or_default(),
            at_unix_s,
            range_nm: args.range_nm,
        };
        let import = build_scenario(&log, &options)
            .map_err(|error| CliError::BadInput(error.to_string()))?;
        (import.scenario, import.notes, None)
    };
    for note in &notes {
        console::warn(&format!("note: {note}"));
    }
    if let Some(coast) = &args.coast {
        let land = crate::coast::add_land(&scenario, coast, args.coast_margin_nm, &args.out)?;
        scenario.land_geojson = Some(land.to_owned());
    }
    let text = scenario
        .to_ron_string()
        .map_err(|error| CliError::Output(error.to_string()))?;
    if let Some(parent) = args
        .out
        .parent()
        .filter(|parent| !parent.as_os_str().is_empty())
    {
        std::fs::create_dir_all(parent).map_err(|error| {
            CliError::Output(format!("cannot create {}: {error}", parent.display()))
        })?;
    }
    let write = |path: &std::path::Path, text: &str| {
        std::fs::write(path, text)
            .map_err(|error| CliError::Output(format!("cannot write {}: {error}", path.display())))
    };
    write(&args.out, &text)?;
    if let Some((path, csv)) = &tracks {
        write(path, csv)?;
        console::line(&format!("wrote {}: the recorded tracks", path.display()));
    }
    // The coast may put a vessel on land, or within the land clearance of
    // it: say so now, with the format's own message, not at the first run.
    if args.coast.is_some()
        && let Err(error) = vorrt_scenarios::Scenario::load(&args.out)
    {
        console::warn(&format!(
            "warning: {} does not validate with its land: {error}",
            args.out.display()
        ));
    }
    console::line(&format!(
        "wrote {}: ownship {:?} and {} targets{}",
        args.out.display(),
        scenario.ownship.name,
        scenario.targets.len(),
        scenario
            .start_time
            .as_deref()
            .map(|time| format!(" at {time}"))
            .unwrap_or_default()
    ));
    Ok(ExitStatus::Success)
}
