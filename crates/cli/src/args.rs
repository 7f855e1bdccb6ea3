//! The command line: subcommands, options and help texts (clap derive).
//!
//! The doc comments here are the `--help` texts, written for a terminal:
//! placeholders like `<scenario name>` are not HTML.
#![allow(rustdoc::invalid_html_tags)]

use clap::{Args, Parser, Subcommand, ValueEnum};
use std::path::PathBuf;

const EXIT_CODES: &str = "\
Exit codes:
  0  success (simulate/demo: every run reached its goal safely and obeyed COLREGs; plan: a safe
     path was found; check: every file is valid; judge: the tracks are safe and compliant;
     batch/merge: once run, whatever the results)
  1  the planner found no safe path, or a run did not reach its goal safely
     (goal not reached, a collision, or the clearance d_th broken) or had a COLREGs finding;
     judge: a collision, d_th broken or a COLREGs finding
  2  bad input or usage: an unreadable or invalid scenario file, a wrong option,
     an output folder that cannot be written; merge: an --out that is one of the inputs,
     or a missing shard without --allow-missing";

/// VORRT-COLREGs path planning for autonomous surface vessels: plan, simulate
/// and evaluate encounters at sea under the collision regulations.
#[derive(Debug, Parser)]
#[command(name = "vorrt", version, about, after_help = EXIT_CODES)]
pub(crate) struct Cli {
    /// What to do.
    #[command(subcommand)]
    pub(crate) command: Command,
}

/// The subcommands.
#[derive(Debug, Subcommand)]
pub(crate) enum Command {
    /// Run a scenario in closed loop and report on it.
    ///
    /// Ownship plans, follows its plan and replans when a target strays from
    /// the prediction or a new encounter arises; targets move as the scenario
    /// says. Prints a summary table (per target: encounter, role, minimum
    /// distance, compliance, score; overall: goal reached, minimum distance
    /// against d_th, path and time overhead, planner calls and time) and writes
    /// DIR/report.json, DIR/trajectories.svg/.png, DIR/distance.svg/.png,
    /// DIR/speed.svg/.png and
    /// DIR/trajectory.csv; for a geographic scenario also
    /// DIR/trajectory.geojson and DIR/trajectory.gpx. Exits 0 when the run
    /// reached its goal safely and obeyed COLREGs, 1 when it did not (a
    /// COLREGs finding included, as vorrt judge exits on the same tracks).
    #[expect(
        clippy::doc_markdown,
        reason = "clap help text, printed verbatim by --help"
    )]
    #[command(after_help = EXIT_CODES)]
    Simulate {
        /// The scenario file (RON; see docs/scenario-format.md).
        scenario: PathBuf,
        /// Planner seed [default: the scenario's `seed`, else 1].
        #[arg(long, value_name = "N")]
        seed: Option<u64>,
        /// Output folder [default: out/<scenario name>].
        #[arg(long, value_name = "DIR")]
        out: Option<PathBuf>,
        /// Also write DIR/run.nmea: the run as AIS (ownship as !AIVDO, targets
        /// as !AIVDM; message types 1 and 5; NMEA 4.10 tag-block times) for a
        /// chart plotter's replay. A local scenario needs --ais-origin.
        #[arg(long)]
        ais: bool,
        /// Where --ais puts a local scenario's origin (0, 0): LAT,LON in
        /// degrees (e.g. 50.3,-1.0). A geographic scenario has its own.
        #[arg(long, value_name = "LAT,LON", requires = "ais")]
        ais_origin: Option<String>,
    },
    /// Plan once from the start state and print the plan as JSON.
    ///
    /// Prints waypoints (time s, east and north m, course deg) and search
    /// statistics on stdout; for a geographic scenario, --format geojson
    /// prints a GeoJSON LineString and --format gpx a GPX 1.1 route instead. When no safe path exists, prints the planner's
    /// reason on stderr and exits 1.
    #[expect(
        clippy::doc_markdown,
        reason = "clap help text, printed verbatim by --help"
    )]
    #[command(after_help = EXIT_CODES)]
    Plan {
        /// The scenario file (RON).
        scenario: PathBuf,
        /// Planner seed [default: the scenario's `seed`, else 1].
        #[arg(long, value_name = "N")]
        seed: Option<u64>,
        /// Output format (geojson and gpx need a geographic scenario).
        #[arg(long, value_enum, default_value_t = PlanFormat::Json)]
        format: PlanFormat,
    },
    /// Validate scenario files.
    ///
    /// Prints `ok: <file>` for each valid file. For an invalid one, prints the
    /// problem naming the file, the line or the field, and exits 2.
    #[command(after_help = EXIT_CODES)]
    Check {
        /// One or more scenario files (RON).
        #[arg(required = true, value_name = "SCENARIO")]
        scenarios: Vec<PathBuf>,
    },
    /// Run every bundled scenario and write an HTML page of the results.
    ///
    /// Runs the paper scenarios and the Imazu problems (in parallel), writes a
    /// folder per scenario as `simulate` does (DIR/<group>/<file stem>/), and
    /// DIR/index.html: a summary table of every run, then every scenario's
    /// plots and figures. Open index.html in a browser. One line per run on
    /// the console, in the scenarios' order; exits 0 when every run reached
    /// its goal safely and obeyed COLREGs (simulate's judgement), 1 when one
    /// did not, 2 when one could not run.
    #[command(after_help = EXIT_CODES)]
    Demo {
        /// Output folder.
        #[arg(long, value_name = "DIR", default_value = "out/demo")]
        out: PathBuf,
        /// Planner seed for every scenario [default: each scenario's `seed`, else 1].
        #[arg(long, value_name = "N")]
        seed: Option<u64>,
        /// Scenario folder: its *.ron files and those of its immediate
        /// subfolders, one group per folder [default: paper/ and imazu/ of the
        /// bundled fixtures/].
        #[arg(long, value_name = "DIR")]
        fixtures: Option<PathBuf>,
        /// Run only the scenarios with this name or file stem (repeatable).
        #[arg(long, value_name = "NAME")]
        only: Vec<String>,
    },
    /// Run a Monte Carlo batch: generated scenarios or a folder of files.
    ///
    /// Runs every scenario in closed loop in parallel and writes DIR/rows.csv
    /// (one row per scenario), DIR/summary.json (rates, compliance per rule,
    /// percentiles), DIR/run.json, DIR/min_distance.svg, DIR/planning_time.svg
    /// and DIR/failures/*.ron. Exits 0 once the batch has run, whatever its
    /// results. See docs/evaluation.md.
    #[expect(
        clippy::doc_markdown,
        reason = "clap help text, printed verbatim by --help"
    )]
    #[command(after_help = EXIT_CODES)]
    Batch(BatchArgs),
    /// Write generated scenarios as .ron files (the ones `batch --generate`
    /// would run with the same options).
    #[command(after_help = EXIT_CODES)]
    Generate(GenerateArgs),
    /// Turn an AIS log (NMEA 0183) into a geographic scenario file.
    ///
    /// Reads !AIVDM/!AIVDO message types 1, 2, 3, 5, 18, 19 and 24 (multi-
    /// sentence messages reassembled, NMEA 4.0 tag block times), estimates
    /// every vessel's state at the chosen time by dead reckoning from its last
    /// position report, and writes ownship (with the goal given) and every
    /// vessel within the range. Skipped lines are counted on stderr. See
    /// docs/real-data.md.
    #[command(after_help = EXIT_CODES)]
    ImportAis(crate::import_ais::ImportAisArgs),
    /// Clip and simplify a coastline into the land GeoJSON of a scenario.
    ///
    /// Reads land polygons from GeoJSON, TopoJSON (e.g. Natural Earth's
    /// land-10m.json from the npm package world-atlas) or an ESRI shapefile
    /// (e.g. GSHHS L1), keeps the part inside --bbox, simplifies it to
    /// --tolerance-m in a local metric frame keeping every ring valid, drops
    /// pieces under --min-area-m2 and writes GeoJSON (RFC 7946) for a
    /// scenario's land_geojson. No land in the box is a warning, not an error.
    /// See docs/decisions/0038-coastline-sources-and-simplification.md.
    #[expect(
        clippy::doc_markdown,
        reason = "clap help text, printed verbatim by --help"
    )]
    #[command(after_help = EXIT_CODES)]
    Coast(crate::coast::CoastArgs),
    /// Judge recorded tracks (any planner's) against COLREGs, as the
    /// project's own evaluation judges a run.
    ///
    /// Reads trajectory.csv (as `simulate` writes it), GeoJSON LineStrings
    /// with per-point times, or an AIS log; puts every vessel on one clock
    /// (docs/judge.md); judges safety, every rule's duties and path quality
    /// with the same evaluation as `simulate`; prints a table and writes
    /// DIR/judgement.json and the trajectory and distance plots. Exits 0
    /// when the tracks are safe (no collision, d_th kept) and compliant, 1
    /// when not, 2 on bad input.
    #[expect(
        clippy::doc_markdown,
        reason = "clap help text, printed verbatim by --help"
    )]
    #[command(after_help = EXIT_CODES)]
    Judge(crate::judge::JudgeArgs),
    /// Merge the outputs of the shards of one batch into one rows.csv,
    /// summary.json, run.json and plots; refuses shards of different
    /// batches, an --out that is one of the inputs, and missing shards
    /// (exit 2) unless --allow-missing is given.
    #[command(after_help = EXIT_CODES)]
    Merge(MergeArgs),
}

/// Which generator.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub(crate) enum Kind {
    /// Open-sea encounters: targets on near-collision courses (see
    /// docs/evaluation.md).
    OpenSea,
    /// Open-sea encounters among islands and a coast near the route
    /// (headlands, bays, lagoons; see docs/evaluation.md).
    Coastal,
    /// Crossings of a traffic separation scheme.
    Tss,
}

/// How the generated targets move.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub(crate) enum BehaviourName {
    /// Straight for their goals at constant speed (the paper's).
    Constant,
    /// Give way to ownship by COLREGs when they must (35° to starboard).
    Colregs,
    /// Course and speed wander about the nominal (5°, 0.5 kn).
    Noisy,
    /// Turn 30-90° to a random side, unannounced, before the closest approach.
    SuddenTurn,
}

/// Lane layout of a generated TSS.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub(crate) enum DirectionName {
    /// One lane, traffic flowing west.
    Westbound,
    /// One lane, traffic flowing east.
    Eastbound,
    /// Two lanes with a separation zone.
    TwoWay,
}

/// The generator options shared by `batch --generate` and `generate`.
#[derive(Debug, Clone, Args)]
pub(crate) struct GeneratorArgs {
    /// Open sea and coastal: number of targets per scenario (1-256; coastal
    /// default 1).
    #[arg(long, value_name = "N")]
    pub(crate) targets: Option<usize>,
    /// TSS: traffic density, targets per nautical mile of lane [default: 1].
    #[arg(long, value_name = "PER_NM")]
    pub(crate) density: Option<f64>,
    /// TSS: lane layout.
    #[arg(long, value_enum, default_value = "westbound")]
    pub(crate) direction: DirectionName,
    /// TSS: lane width, nautical miles.
    #[arg(long, value_name = "NM", default_value_t = 1.0)]
    pub(crate) lane_width: f64,
    /// Number of scenarios in the whole batch (before sharding).
    #[arg(long, value_name = "K", default_value_t = 100,
          value_parser = clap::value_parser!(u64).range(1..))]
    pub(crate) count: u64,
    /// Batch seed: scenario k is drawn from stream k of this seed and
    /// simulated with a seed derived from (seed, k).
    #[arg(long, value_name = "S", default_value_t = 1)]
    pub(crate) seed: u64,
    /// How the targets move.
    #[arg(long, value_enum, default_value = "constant")]
    pub(crate) behaviour: BehaviourName,
    /// Only the scenarios k with k % n == i (e.g. --shard
    /// $SLURM_ARRAY_TASK_ID/$SLURM_ARRAY_TASK_COUNT).
    #[expect(
        clippy::doc_markdown,
        reason = "clap help text, printed verbatim by --help"
    )]
    #[arg(long, value_name = "i/n")]
    pub(crate) shard: Option<String>,
}

/// `vorrt batch`.
#[derive(Debug, Clone, Args)]
pub(crate) struct BatchArgs {
    /// Generate the scenarios.
    #[arg(
        long,
        value_enum,
        value_name = "KIND",
        conflicts_with = "dir",
        required_unless_present = "dir"
    )]
    pub(crate) generate: Option<Kind>,
    /// Run the scenario files (*.ron, *.json) of this folder instead, in file-name
    /// order; each with its own `seed` if it has one.
    #[arg(long, value_name = "FOLDER")]
    pub(crate) dir: Option<PathBuf>,
    /// The generator, seed and shard options.
    #[command(flatten)]
    pub(crate) generator: GeneratorArgs,
    /// Worker threads, at least 1 [default: one per core].
    #[arg(long, value_name = "N",
          value_parser = clap::builder::RangedU64ValueParser::<usize>::new().range(1..))]
    pub(crate) jobs: Option<usize>,
    /// Output folder.
    #[arg(long, value_name = "DIR")]
    pub(crate) out: PathBuf,
    /// Also write every run's trajectory.csv, into
    /// `DIR/runs/<index>-<scenario name>/`.
    #[arg(long)]
    pub(crate) trajectories: bool,
}

/// `vorrt generate`.
#[derive(Debug, Clone, Args)]
pub(crate) struct GenerateArgs {
    /// Which generator.
    #[arg(value_enum)]
    pub(crate) kind: Kind,
    /// The generator, seed and shard options.
    #[command(flatten)]
    pub(crate) generator: GeneratorArgs,
    /// Output folder for the .ron files.
    #[arg(long, value_name = "DIR")]
    pub(crate) out: PathBuf,
}

/// `vorrt merge`.
#[derive(Debug, Clone, Args)]
pub(crate) struct MergeArgs {
    /// Shard output folders of `vorrt batch` (each holding rows.csv and
    /// run.json); they must be shards of one batch.
    #[arg(required = true, value_name = "DIR")]
    pub(crate) inputs: Vec<PathBuf>,
    /// Output folder; not one of the inputs (refused: it would overwrite
    /// that shard).
    #[arg(long, value_name = "DIR")]
    pub(crate) out: PathBuf,
    /// Merge even when some shards of the batch are missing (a warning
    /// names them, and run.json lists them as missing shards); without it a
    /// missing shard is an error (exit 2) and nothing is written.
    #[arg(long)]
    pub(crate) allow_missing: bool,
}

/// What `vorrt plan` prints.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub(crate) enum PlanFormat {
    /// The plan schema of docs/report-format.md.
    Json,
    /// A GeoJSON Feature with the plan's LineString (geographic scenarios).
    #[expect(
        clippy::doc_markdown,
        reason = "clap help text, printed verbatim by --help"
    )]
    Geojson,
    /// A GPX 1.1 route (geographic scenarios).
    Gpx,
}
