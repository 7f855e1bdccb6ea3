//! The command line's work as functions, for other front ends (the Python
//! binding, `python/`): the same `trajectory.csv`, the same judgement of
//! recorded tracks and the same generated scenarios as `vorrt simulate`,
//! `vorrt judge` and `vorrt generate`, and the whole command line run
//! in-process ([`run_command_line`]). Nothing here prints, except the
//! command line itself. Errors are the command line's messages.

use crate::args::{BehaviourName, DirectionName, GeneratorArgs, Kind};
use crate::judge::{self, TracksFormat, build};
use std::ffi::OsString;
use vorrt_scenarios::batch::BatchItem;
use vorrt_scenarios::{Scenario, SimulationRecord};

/// Runs the command line `vorrt ARGS...` in this process (`args` without
/// the program name) and gives its exit code, as [`crate::main_entry`]:
/// what it prints goes to this process's standard output and error.
#[must_use]
pub fn run_command_line(args: Vec<OsString>) -> u8 {
    crate::run_parsed(std::iter::once(OsString::from("vorrt")).chain(args))
}

/// `trajectory.csv` of a run, byte for byte as `vorrt simulate` writes it.
///
/// # Errors
/// The CSV writer's message (it writes to memory: not expected).
pub fn trajectory_csv(scenario: &Scenario, record: &SimulationRecord) -> Result<String, String> {
    crate::export::trajectory_csv(scenario, record).map_err(|error| error.to_string())
}

/// The options of [`judge_csv`]: `vorrt judge`'s, with its defaults.
#[derive(Debug, Clone, PartialEq)]
pub struct JudgeOptions {
    /// Ownship's name among the tracks (`--ownship`); `None`: the
    /// scenario's ownship, else the vessel marked as ownship, else the first.
    pub ownship: Option<String>,
    /// The clearance `d_th`, metres (`--d-th`); `None`: the scenario's, else 200.
    pub d_th_m: Option<f64>,
    /// Resampling step, seconds (`--step-s`); `None`: keep shared stamps.
    pub step_s: Option<f64>,
    /// A stretch longer than this without a fix is a gap, seconds.
    pub max_gap_s: f64,
    /// Ownship reached its goal if its track came this close, metres.
    pub goal_tolerance_m: f64,
    /// Length of a vessel neither the scenario nor the tracks give, metres.
    pub length_m: f64,
    /// Ownship's rate-of-turn limit, degrees per second; `None`: a turn of
    /// radius one length where its length is known, else the rate is
    /// reported, not judged.
    pub max_turn_rate_deg_s: Option<f64>,
    /// A fix farther from the vessel's last than this speed allows is a
    /// jump, rejected, knots (`--max-speed-kn`).
    pub max_speed_kn: f64,
    /// The width of navigable water, metres (`--sea-room-m`); `None`: the
    /// scenario's, else open sea (decision 50).
    pub sea_room_m: Option<f64>,
}

impl Default for JudgeOptions {
    fn default() -> Self {
        Self {
            ownship: None,
            d_th_m: None,
            step_s: None,
            max_gap_s: judge::DEFAULT_MAX_GAP_S,
            goal_tolerance_m: judge::DEFAULT_GOAL_TOLERANCE_M,
            length_m: vorrt_ais::DEFAULT_LENGTH_M,
            max_turn_rate_deg_s: None,
            max_speed_kn: judge::DEFAULT_MAX_SPEED_KN,
            sea_room_m: None,
        }
    }
}

/// Judges tracks in the CSV of `trajectory.csv` (columns `time_s`,
/// `vessel`, `east_m,north_m` or `lat_deg,lon_deg`, ...) as `vorrt judge
/// --format csv` does, against `scenario` when given; `file` names the
/// tracks in messages. Gives `judgement.json` as `vorrt judge` writes it
/// (pretty JSON, without the final line end).
///
/// # Errors
/// `vorrt judge`'s message for invalid tracks or options.
pub fn judge_csv(
    file: &str,
    text: &str,
    scenario: Option<Scenario>,
    options: &JudgeOptions,
) -> Result<String, String> {
    let options = build::Options {
        tracks_file: file.to_owned(),
        ownship: options.ownship.clone(),
        d_th_m: options.d_th_m,
        step_s: options.step_s,
        max_gap_s: options.max_gap_s,
        goal_tolerance_m: options.goal_tolerance_m,
        default_length_m: options.length_m,
        max_turn_rate_deg_s: options.max_turn_rate_deg_s,
        max_speed_kn: options.max_speed_kn,
        sea_room_m: options.sea_room_m,
    };
    let (_, _, judgement) = judge::judge_text(text, TracksFormat::Csv, scenario, &options)
        .map_err(|error| error.to_string())?;
    serde_json::to_string_pretty(&judgement)
        .map_err(|error| format!("cannot write the judgement as JSON: {error}"))
}

/// The generator options of `vorrt generate` and `vorrt batch --generate`,
/// with their defaults.
#[derive(Debug, Clone, PartialEq)]
pub struct GenerateOptions {
    /// Open sea: targets per scenario (`--targets`, required there);
    /// coastal: the same, default 1.
    pub targets: Option<usize>,
    /// TSS: targets per nautical mile of lane (`--density`).
    pub density_per_nm: Option<f64>,
    /// TSS lane layout: `westbound`, `eastbound` or `two-way`.
    pub direction: String,
    /// TSS lane width, nautical miles.
    pub lane_width_nm: f64,
    /// Scenarios in the whole batch, before sharding.
    pub count: u64,
    /// The batch seed.
    pub seed: u64,
    /// How targets move: `constant`, `colregs`, `noisy` or `sudden-turn`.
    pub behaviour: String,
    /// Only the scenarios of shard `i/n`.
    pub shard: Option<String>,
}

impl Default for GenerateOptions {
    fn default() -> Self {
        Self {
            targets: None,
            density_per_nm: None,
            direction: "westbound".into(),
            lane_width_nm: 1.0,
            count: 100,
            seed: 1,
            behaviour: "constant".into(),
            shard: None,
        }
    }
}

/// The scenarios `vorrt batch --generate KIND` runs with these options,
/// each with the seed the batch simulates it with (`kind`: `open-sea`,
/// `coastal` or `tss`).
///
/// # Errors
/// The command line's message for a bad kind, option or shard.
pub fn generate(kind: &str, options: &GenerateOptions) -> Result<Vec<BatchItem>, String> {
    let kind = match kind {
        "open-sea" | "open_sea" => Kind::OpenSea,
        "coastal" => Kind::Coastal,
        "tss" => Kind::Tss,
        other => {
            return Err(format!(
                "kind is {other:?}, expected \"open-sea\", \"coastal\" or \"tss\""
            ));
        }
    };
    let behaviour = match options.behaviour.as_str() {
        "constant" => BehaviourName::Constant,
        "colregs" => BehaviourName::Colregs,
        "noisy" => BehaviourName::Noisy,
        "sudden-turn" | "sudden_turn" => BehaviourName::SuddenTurn,
        other => {
            return Err(format!(
                "behaviour is {other:?}, expected \"constant\", \"colregs\", \"noisy\" or \"sudden-turn\""
            ));
        }
    };
    let direction = match options.direction.as_str() {
        "westbound" => DirectionName::Westbound,
        "eastbound" => DirectionName::Eastbound,
        "two-way" | "two_way" => DirectionName::TwoWay,
        other => {
            return Err(format!(
                "direction is {other:?}, expected \"westbound\", \"eastbound\" or \"two-way\""
            ));
        }
    };
    if options.count == 0 {
        return Err("count is 0, expected at least 1".into());
    }
    let args = GeneratorArgs {
        targets: options.targets,
        density: options.density_per_nm,
        direction,
        lane_width: options.lane_width_nm,
        count: options.count,
        seed: options.seed,
        behaviour,
        shard: options.shard.clone(),
    };
    crate::batch::items_of(&args, Some(kind), None)
        .map(|(items, _)| items)
        .map_err(|error| error.to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn crossing() -> Scenario {
        vorrt_scenarios::fixtures::find("paper/crossing")
            .expect("fixture")
            .load()
            .expect("valid")
    }

    #[test]
    fn trajectory_csv_is_the_simulate_export() {
        let scenario = crossing();
        let record = vorrt_scenarios::simulate(&scenario, 1).expect("runs");
        let text = trajectory_csv(&scenario, &record).expect("csv");
        assert!(text.starts_with("time_s,vessel,"), "{text}");
        assert_eq!(
            text.lines().count(),
            1 + record.times_s.len() * (1 + scenario.targets.len())
        );
    }

    #[test]
    fn judging_a_simulated_run_agrees_with_its_report() {
        let scenario = crossing();
        let record = vorrt_scenarios::simulate(&scenario, 1).expect("runs");
        let text = trajectory_csv(&scenario, &record).expect("csv");
        let json =
            judge_csv("run.csv", &text, Some(scenario), &JudgeOptions::default()).expect("judged");
        let value: serde_json::Value = serde_json::from_str(&json).expect("json");
        assert_eq!(value["safe_and_compliant"], serde_json::Value::Bool(true));
        assert_eq!(value["input"]["tracks_file"], "run.csv");
        let error = judge_csv("bad.csv", "time_s\n1\n", None, &JudgeOptions::default())
            .expect_err("no vessel column");
        assert!(error.contains("bad.csv"), "{error}");
    }

    #[test]
    fn generate_gives_the_batch_items_and_refuses_bad_options() {
        let options = GenerateOptions {
            targets: Some(2),
            count: 4,
            seed: 7,
            ..GenerateOptions::default()
        };
        let items = generate("open-sea", &options).expect("generates");
        assert_eq!(items.len(), 4);
        assert!(items.iter().all(|item| item.scenario.targets.len() == 2));
        let shard = GenerateOptions {
            shard: Some("1/2".into()),
            ..options.clone()
        };
        let odd = generate("open-sea", &shard).expect("shard");
        assert_eq!(
            odd.iter().map(|item| item.index).collect::<Vec<_>>(),
            [1, 3]
        );
        assert_eq!(odd[0].scenario, items[1].scenario);
        assert!(generate("lake", &options).unwrap_err().contains("lake"));
        let no_targets = GenerateOptions {
            targets: None,
            ..options
        };
        assert!(
            generate("open-sea", &no_targets)
                .unwrap_err()
                .contains("--targets")
        );
    }

    #[test]
    fn generate_coastal_gives_land_and_one_target_by_default() {
        let options = GenerateOptions {
            count: 2,
            seed: 11,
            ..GenerateOptions::default()
        };
        let items = generate("coastal", &options).expect("generates");
        assert_eq!(items.len(), 2);
        for item in &items {
            assert_eq!(item.scenario.targets.len(), 1);
            assert!(!item.scenario.land.is_empty(), "{}", item.scenario.name);
        }
        assert_eq!(items, generate("coastal", &options).expect("again"));
        let density = GenerateOptions {
            density_per_nm: Some(1.0),
            ..options
        };
        assert!(
            generate("coastal", &density)
                .unwrap_err()
                .contains("--density")
        );
    }

    #[test]
    fn the_command_line_runs_in_process() {
        assert_eq!(run_command_line(vec!["--version".into()]), 0);
        assert_eq!(run_command_line(vec!["no-such-command".into()]), 2);
    }
}
