//! What `vorrt judge` writes: `judgement.json` (the report of
//! `report.json` with the judge's `input` section) and the console table.

use crate::judge::build::Input;
use crate::report::Report;
use serde::{Deserialize, Serialize};
use vorrt_scenarios::Evaluation;

/// `judgement.json`: every field of `report.json` (the planner fields are
/// zero: no planner ran), `safe_and_compliant`, and how the tracks were read.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub(crate) struct Judgement {
    /// The judgement in the report's schema (`docs/report-format.md`).
    #[serde(flatten)]
    pub(crate) report: Report,
    /// No collision and no grounding, `d_th` and the land clearance kept,
    /// no COLREGs finding
    /// (`vorrt_scenarios::Evaluation::safe_and_compliant`) and no encounter
    /// undecided: exit code 0.
    pub(crate) safe_and_compliant: bool,
    /// The targets whose encounter the tracks cannot decide (still closing
    /// when they end, a reported rest the motion contradicts, a closest
    /// approach not reported: `targets[].undecided` says which): neither
    /// passed nor safe.
    pub(crate) undecided: Vec<String>,
    /// How the tracks were read, resampled and completed.
    pub(crate) input: Input,
}

impl Judgement {
    /// The judgement `evaluation` reports as `report`, the tracks read as
    /// `input` says.
    pub(crate) fn new(evaluation: &Evaluation, report: Report, mut input: Input) -> Self {
        for (vessel, noise) in input.observation.iter_mut().zip(&evaluation.noise) {
            vessel.window_s = noise.window_s;
            vessel.turn_tolerance_deg = noise.turn_tolerance_rad.to_degrees();
            vessel.action_detection_deg = noise.action_detection_rad.to_degrees();
        }
        let undecided: Vec<String> = evaluation
            .targets
            .iter()
            .filter(|target| target.undecided.is_some())
            .map(|target| target.name.clone())
            .collect();
        Self {
            report,
            safe_and_compliant: evaluation.safe_and_compliant() && undecided.is_empty(),
            undecided,
            input,
        }
    }
}

/// One line per judged vessel on how it was observed (jitter, window,
/// thresholds, jumps), and one on what its status brings.
fn write_observation(text: &mut String, input: &Input) {
    use std::fmt::Write as _;
    for vessel in &input.observation {
        let jitter = vessel
            .position_noise_m
            .map_or_else(|| "unknown".to_owned(), |m| format!("{m:.1} m"));
        let _ = writeln!(
            *text,
            "  observed: {:?}: jitter {jitter}, courses over {:.0} s, turns above {:.1}°, action at {:.1}°{}",
            vessel.name,
            vessel.window_s,
            vessel.turn_tolerance_deg,
            vessel.action_detection_deg,
            if vessel.jumps_rejected > 0 {
                format!(", {} jumping fixes rejected", vessel.jumps_rejected)
            } else {
                String::new()
            }
        );
        if let Some(rule) = &vessel.rule_18 {
            let _ = writeln!(*text, "  status: {:?}: {rule}", vessel.name);
        }
    }
}

/// The table `vorrt judge` prints.
pub(crate) fn table(judgement: &Judgement) -> String {
    use std::fmt::Write as _;
    let report = &judgement.report;
    let input = &judgement.input;
    let mut text = String::new();
    let _ = writeln!(
        text,
        "judging {} ({}), ownship {:?}, against {}; d_th = {:.0} m",
        input.tracks_file,
        input.tracks_format,
        input.ownship,
        input
            .scenario_file
            .as_deref()
            .unwrap_or("a scenario synthesized from the tracks"),
        report.d_th_m
    );
    let clock = &input.clock;
    let _ = writeln!(
        text,
        "clock: {} samples from {:.1} s to {:.1} s, {} {:.2} s",
        clock.samples,
        clock.from_s,
        clock.to_s,
        if clock.resampled {
            "resampled every"
        } else {
            "the file's own time stamps, median step"
        },
        clock.step_s
    );
    for line in input
        .assumptions
        .iter()
        .map(|a| format!("assumed: {a}"))
        .chain(input.left_out.iter().map(|l| format!("not judged: {l}")))
        .chain(input.gaps.iter().map(|gap| gap.describe(input.max_gap_s)))
    {
        let _ = writeln!(text, "  {line}");
    }
    write_observation(&mut text, input);
    report.write_target_table(&mut text);
    let _ = writeln!(text);
    let _ = writeln!(
        text,
        "collision:      {}",
        if report.collision { "YES" } else { "no" }
    );
    report.write_safety_lines(&mut text);
    let arrival = match report.arrival_time_s {
        Some(time_s) => format!("yes, at {:.1} min", time_s / 60.0),
        None => format!("no (not within {:.0} m of it)", input.goal_tolerance_m),
    };
    let _ = writeln!(text, "reached goal:   {arrival}");
    report.write_overhead_lines(&mut text);
    if let Some(rule10) = &report.rule10 {
        rule10.write_lines(&mut text);
    }
    let quality = &report.path_quality;
    let _ = writeln!(
        text,
        "path quality:   largest rate of turn {:.2}°/s{}, {} turn reversals, {:.1}° of course change per nm",
        quality.max_turn_rate_deg_s,
        quality
            .turn_rate_limit_deg_s
            .map_or_else(String::new, |limit| format!(" (limit {limit:.2}°/s)")),
        quality.turn_reversals,
        quality.course_change_deg_per_nm
    );
    for finding in &quality.findings {
        let _ = writeln!(text, "                - {finding}");
    }
    for target in &report.targets {
        if let Some(why) = &target.undecided {
            let _ = writeln!(text, "undecided:      {:?}: {why}", target.name);
        }
    }
    let _ = writeln!(
        text,
        "verdict:        {}",
        if judgement.safe_and_compliant {
            "safe and compliant"
        } else if judgement.undecided.is_empty() {
            "NOT safe and compliant"
        } else {
            "NOT safe and compliant (undecided)"
        }
    );
    text
}
