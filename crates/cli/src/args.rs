//! The command line: subcommands, options and help texts (clap derive).
//!
//! The doc comments here are the `--help` texts, written for a terminal:
//! placeholders like `<scenario name>` are not HTML.
#![allow(rustdoc::invalid_html_tags)]

use clap::{Parser, Subcommand};
use std::path::PathBuf;

const EXIT_CODES: &str = "\
Exit codes:
  0  success (simulate/demo: every run reached its goal safely; plan: a safe path was found; check: every file is valid)
  1  the planner found no safe path, or a run did not reach its goal safely
     (goal not reached, a collision, or the clearance d_th broken)
  2  bad input or usage: an unreadable or invalid scenario file, a wrong option,
     an output folder that cannot be written";

/// VORRT-COLREGs path planning for autonomous surface vessels: plan, simulate
/// and evaluate encounters at sea under the collision regulations.
#[derive(Debug, Parser)]
#[command(name = "vorrt", version, about, after_help = EXIT_CODES)]
pub struct Cli {
    /// What to do.
    #[command(subcommand)]
    pub command: Command,
}

/// The subcommands.
#[derive(Debug, Subcommand)]
pub enum Command {
    /// Run a scenario in closed loop and report on it.
    ///
    /// Ownship plans, follows its plan and replans when a target strays from
    /// the prediction or a new encounter arises; targets move as the scenario
    /// says. Prints a summary table (per target: encounter, role, minimum
    /// distance, compliance, score; overall: goal reached, minimum distance
    /// against d_th, path overhead, planner calls and time) and writes
    /// DIR/report.json, DIR/trajectories.svg/.png, DIR/distance.svg/.png and
    /// DIR/trajectory.csv; for a geographic scenario also
    /// DIR/trajectory.geojson and DIR/trajectory.gpx.
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
    },
    /// Plan once from the start state and print the plan as JSON.
    ///
    /// Prints waypoints (time s, east and north m, course deg) and search
    /// statistics on stdout; for a geographic scenario, --format geojson
    /// prints a GeoJSON LineString and --format gpx a GPX 1.1 route instead. When no safe path exists, prints the planner's
    /// reason on stderr and exits 1.
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
    /// plots and figures. Open index.html in a browser.
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
    #[command(after_help = EXIT_CODES)]
    Batch(crate::batch::BatchArgs),
    /// Write generated scenarios as .ron files (the ones `batch --generate`
    /// would run with the same options).
    #[command(after_help = EXIT_CODES)]
    Generate(crate::batch::GenerateArgs),
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
    /// Merge the outputs of several batch shards into one rows.csv,
    /// summary.json and plots.
    #[command(after_help = EXIT_CODES)]
    Merge(crate::batch::MergeArgs),
}

/// What `vorrt plan` prints.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum PlanFormat {
    /// The plan schema of docs/report-format.md.
    Json,
    /// A GeoJSON Feature with the plan's LineString (geographic scenarios).
    Geojson,
    /// A GPX 1.1 route (geographic scenarios).
    Gpx,
}
