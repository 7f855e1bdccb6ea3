//! `vorrt judge`: any planner's recorded tracks judged by the project's own
//! evaluation.
//!
//! The tracks (`trajectory.csv`, `GeoJSON` with per-point times, or an AIS
//! log) are read ([`tracks`], [`formats`]), put on one clock
//! ([`resample`]) and rebuilt into the run record and scenario that
//! `vorrt_scenarios::evaluate` reads ([`build`]); that one evaluation judges
//! them, exactly as it judges `vorrt simulate`'s runs, and [`output`] writes
//! the verdict. See `docs/judge.md`.

pub(crate) mod build;
pub(crate) mod formats;
pub(crate) mod observation;
pub(crate) use observation::DEFAULT_MAX_SPEED_KN;
pub(crate) mod output;
pub(crate) mod resample;
pub(crate) mod risk;
pub(crate) mod tracks;

use crate::console;
use crate::error::{CliError, ExitStatus};
use crate::report::Report;
use clap::{Args, ValueEnum};
use std::path::{Path, PathBuf};

/// The default gap limit, seconds: longer without a fix is reported.
pub(crate) const DEFAULT_MAX_GAP_S: f64 = 120.0;
/// The default goal tolerance, metres.
pub(crate) const DEFAULT_GOAL_TOLERANCE_M: f64 = 100.0;

/// The file `vorrt judge` writes its verdict to.
pub(crate) const JUDGEMENT_JSON: &str = "judgement.json";

/// The track formats.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub(crate) enum TracksFormat {
    /// `trajectory.csv` as `vorrt simulate` writes it (or any CSV with
    /// `time_s`/`time`, `vessel` and `east_m,north_m` or `lat_deg,lon_deg`).
    Csv,
    /// GeoJSON LineStrings with per-point times (`times_s`, `coordTimes` or `times`).
    #[expect(
        clippy::doc_markdown,
        reason = "clap help text, printed verbatim by --help"
    )]
    Geojson,
    /// An AIS log: NMEA 0183 !AIVDM/!AIVDO with NMEA 4.0 tag-block times.
    Ais,
}

/// `vorrt judge`.
#[derive(Debug, Clone, Args)]
pub(crate) struct JudgeArgs {
    /// The recorded tracks: trajectory.csv, GeoJSON or an AIS log.
    #[expect(
        clippy::doc_markdown,
        reason = "clap help text, printed verbatim by --help"
    )]
    pub(crate) tracks: PathBuf,
    /// The scenario the tracks sail (RON): ownship's goal, the lengths,
    /// d_th and the rule constants [default: synthesized from the tracks:
    /// goal = ownship's last position, d_th 200 m, lengths from the tracks
    /// or --length-m].
    #[expect(
        clippy::doc_markdown,
        reason = "clap help text, printed verbatim by --help"
    )]
    #[arg(long, value_name = "SCENARIO.ron")]
    pub(crate) scenario: Option<PathBuf>,
    /// Ownship's name (or MMSI) among the tracks [default: the scenario's
    /// ownship, else the vessel the file marks as ownship, else the first].
    #[arg(long, value_name = "NAME")]
    pub(crate) ownship: Option<String>,
    /// Output folder [default: out/judge/<tracks file stem>].
    #[arg(long, value_name = "DIR")]
    pub(crate) out: Option<PathBuf>,
    /// The tracks' format [default: from the file's extension, else its content].
    #[arg(long, value_enum)]
    pub(crate) format: Option<TracksFormat>,
    /// The clearance d_th, metres [default: the scenario's, else 200].
    #[expect(
        clippy::doc_markdown,
        reason = "clap help text, printed verbatim by --help"
    )]
    #[arg(long, value_name = "M")]
    pub(crate) d_th: Option<f64>,
    /// Resample every vessel at this step, seconds [default: keep the time
    /// stamps when all vessels share them, else their median step].
    #[arg(long, value_name = "S")]
    pub(crate) step_s: Option<f64>,
    /// Report a stretch longer than this without a fix as a gap, seconds.
    #[arg(long, value_name = "S", default_value_t = DEFAULT_MAX_GAP_S)]
    pub(crate) max_gap_s: f64,
    /// Ownship reached its goal if its track came this close, metres.
    #[arg(long, value_name = "M", default_value_t = DEFAULT_GOAL_TOLERANCE_M)]
    pub(crate) goal_tolerance_m: f64,
    /// Length of a vessel neither the scenario nor the tracks give, metres.
    #[arg(long, value_name = "M", default_value_t = vorrt_ais::DEFAULT_LENGTH_M)]
    pub(crate) length_m: f64,
    /// Ownship's rate-of-turn limit, degrees per second [default: a turn
    /// of radius one length at its largest speed, where its length is known;
    /// else the rate is reported, not judged].
    #[arg(long, value_name = "DEG_S")]
    pub(crate) max_turn_rate_deg_s: Option<f64>,
    /// A fix farther from the vessel's last than this speed allows is a
    /// jump, rejected, knots.
    #[arg(long, value_name = "KN", default_value_t = observation::DEFAULT_MAX_SPEED_KN)]
    pub(crate) max_speed_kn: f64,
    /// The width of navigable water the vessels are in, metres (confined
    /// water): the risk-of-collision distance is then at most a quarter of
    /// it, never under d_th between the hulls [default: the scenario's
    /// planner.sea_room_nm, else open sea].
    #[expect(
        clippy::doc_markdown,
        reason = "clap help text, printed verbatim by --help"
    )]
    #[arg(long, value_name = "M")]
    pub(crate) sea_room_m: Option<f64>,
}

/// The format of `path`: the one given, else by extension, else by content.
fn detect(path: &Path, text: &str, given: Option<TracksFormat>) -> TracksFormat {
    if let Some(format) = given {
        return format;
    }
    let extension = path
        .extension()
        .map(|e| e.to_string_lossy().to_ascii_lowercase());
    match extension.as_deref() {
        Some("csv") => TracksFormat::Csv,
        Some("geojson" | "json") => TracksFormat::Geojson,
        Some("nmea" | "ais" | "aivdm") => TracksFormat::Ais,
        _ if text.trim_start().starts_with('{') => TracksFormat::Geojson,
        _ if text.contains("!AIVD") => TracksFormat::Ais,
        _ => TracksFormat::Csv,
    }
}

fn positive(name: &str, value: f64) -> Result<f64, CliError> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(CliError::BadInput(format!(
            "--{name} is {value}, expected a finite number greater than 0"
        )))
    }
}

/// Reads the tracks in `text` (of `format`), rebuilds the run and judges
/// it with the one evaluation: what `vorrt judge` and the Python binding's
/// `vorrt.judge` both do.
///
/// # Errors
/// [`CliError::BadInput`] for invalid tracks or options.
pub(crate) fn judge_text(
    text: &str,
    format: TracksFormat,
    scenario: Option<vorrt_scenarios::Scenario>,
    options: &build::Options,
) -> Result<
    (
        build::Rebuilt,
        vorrt_scenarios::Evaluation,
        output::Judgement,
    ),
    CliError,
> {
    let file = options.tracks_file.as_str();
    let tracks = match format {
        TracksFormat::Csv => tracks::read_csv(file, text)?,
        TracksFormat::Geojson => formats::read_geojson(file, text)?,
        TracksFormat::Ais => formats::read_ais(file, text)?,
    };
    let rebuilt = build::rebuild(tracks, scenario, options)?;
    let evaluation = vorrt_scenarios::evaluate(&rebuilt.scenario, &rebuilt.record);
    let mut report = Report::new(&rebuilt.scenario, &rebuilt.record, &evaluation);
    // No planner ran (an empty sum of times is -0).
    report.planning.total_planning_time_s = 0.0;
    let judgement = output::Judgement::new(&evaluation, report, rebuilt.input.clone());
    Ok((rebuilt, evaluation, judgement))
}

/// Runs `vorrt judge`: exit 0 when the tracks are safe and compliant, 1
/// when not.
///
/// # Errors
/// [`CliError::BadInput`] for unreadable or invalid tracks, scenario or
/// options; [`CliError::Output`] when the files cannot be written.
pub(crate) fn judge_command(args: &JudgeArgs) -> Result<ExitStatus, CliError> {
    for (name, value) in [
        ("max-gap-s", Some(args.max_gap_s)),
        ("goal-tolerance-m", Some(args.goal_tolerance_m)),
        ("length-m", Some(args.length_m)),
        ("d-th", args.d_th),
        ("step-s", args.step_s),
        ("max-turn-rate-deg-s", args.max_turn_rate_deg_s),
        ("max-speed-kn", Some(args.max_speed_kn)),
        ("sea-room-m", args.sea_room_m),
    ] {
        if let Some(value) = value {
            positive(name, value)?;
        }
    }
    let file = args.tracks.display().to_string();
    let bytes = std::fs::read(&args.tracks)
        .map_err(|error| CliError::BadInput(format!("cannot read {file}: {error}")))?;
    let text = String::from_utf8_lossy(&bytes);
    let format = detect(&args.tracks, &text, args.format);
    let scenario = args.scenario.as_deref().map(crate::run::load).transpose()?;
    let options = build::Options {
        tracks_file: file,
        ownship: args.ownship.clone(),
        d_th_m: args.d_th,
        step_s: args.step_s,
        max_gap_s: args.max_gap_s,
        goal_tolerance_m: args.goal_tolerance_m,
        default_length_m: args.length_m,
        max_turn_rate_deg_s: args.max_turn_rate_deg_s,
        max_speed_kn: args.max_speed_kn,
        sea_room_m: args.sea_room_m,
    };
    let (rebuilt, evaluation, judgement) = judge_text(&text, format, scenario, &options)?;
    let dir = args.out.clone().unwrap_or_else(|| {
        PathBuf::from("out")
            .join("judge")
            .join(crate::run::folder_name(
                &args
                    .tracks
                    .file_stem()
                    .map_or_else(|| "tracks".into(), |stem| stem.to_string_lossy()),
            ))
    });
    std::fs::create_dir_all(&dir)
        .map_err(|error| CliError::Output(format!("cannot create {}: {error}", dir.display())))?;
    let json = serde_json::to_string_pretty(&judgement).map_err(|error| {
        CliError::Output(format!("cannot write the judgement as JSON: {error}"))
    })?;
    let path = dir.join(JUDGEMENT_JSON);
    std::fs::write(&path, json + "\n")
        .map_err(|error| CliError::Output(format!("cannot write {}: {error}", path.display())))?;
    crate::plot::write_plots(&rebuilt.scenario, &rebuilt.record, &evaluation, &dir)
        .map_err(CliError::Output)?;
    crate::replay::write_replay(
        &rebuilt.scenario,
        &rebuilt.record,
        &evaluation,
        &judgement.report,
        &dir,
    )?;
    console::print(&output::table(&judgement));
    console::line(&format!(
        "\nwrote {}/{{{JUDGEMENT_JSON},trajectories.svg,trajectories.png,distance.svg,distance.png,speed.svg,speed.png,replay.html}}",
        dir.display()
    ));
    Ok(if judgement.safe_and_compliant {
        ExitStatus::Success
    } else {
        ExitStatus::Unsafe
    })
}
