//! From recorded tracks to what the project's evaluation reads: a
//! [`SimulationRecord`] (every vessel on one clock, the clearance and rules,
//! no planner calls) and the [`Scenario`] it is judged against (the one
//! given, or one synthesized from the tracks with stated defaults).

use crate::error::CliError;
use crate::judge::observation::{self, VesselObservation};
use crate::judge::resample::{self, Clock, Gap, MIN_INTERVAL_FRACTION, Prepared, Sampled};
use crate::judge::tracks::{Place, Track, Tracks};
use serde::{Deserialize, Serialize};
use vorrt_colregs::VesselState;
use vorrt_geometry::{DVec2, angle, units};
use vorrt_planner::PlannerConfig;
use vorrt_scenarios::{LocalFrame, Scenario, SimulationRecord, VesselSpec};

/// What the judge is told beyond the tracks.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Options {
    /// The tracks file, for messages.
    pub(crate) tracks_file: String,
    /// Ownship's name (or MMSI) among the tracks.
    pub(crate) ownship: Option<String>,
    /// The clearance `d_th`, metres (overrides the scenario's).
    pub(crate) d_th_m: Option<f64>,
    /// The clock's step, seconds (default: the median step of the fixes).
    pub(crate) step_s: Option<f64>,
    /// A stretch without fixes longer than this is reported as a gap, seconds.
    pub(crate) max_gap_s: f64,
    /// Ownship reached its goal if it came this close, metres.
    pub(crate) goal_tolerance_m: f64,
    /// The length of a vessel neither the tracks nor the scenario give, metres.
    pub(crate) default_length_m: f64,
    /// Ownship's rate-of-turn limit, degrees per second (default: from its
    /// length where known, else none: the rate is reported, not judged).
    pub(crate) max_turn_rate_deg_s: Option<f64>,
    /// A fix farther from the last kept than this speed allows is a jump,
    /// rejected, knots.
    pub(crate) max_speed_kn: f64,
    /// The sea room, metres (overrides the scenario's; decision 50).
    pub(crate) sea_room_m: Option<f64>,
}

/// One judged vessel, as the input described it.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub(crate) struct VesselInput {
    /// Its name in the judgement.
    pub(crate) name: String,
    /// `ownship` or `target`.
    pub(crate) role: String,
    /// Fixes read (after dropping repeated times).
    pub(crate) fixes: usize,
    /// Fixes dropped because an earlier one had the same time.
    pub(crate) duplicate_times: usize,
    /// First fix, seconds on the judgement's clock.
    pub(crate) first_fix_s: f64,
    /// Last fix, seconds.
    pub(crate) last_fix_s: f64,
    /// Length judged with, metres.
    pub(crate) length_m: f64,
    /// Where the length came from: `scenario`, `tracks` or `default`.
    pub(crate) length_from: String,
    /// `recorded` (the file's) or `track` (from the resampled positions).
    pub(crate) courses_from: String,
    /// `recorded` or `track`.
    pub(crate) speeds_from: String,
}

/// How the tracks were read and turned into a run: the `input` section of
/// `judgement.json` (see `docs/judge.md`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub(crate) struct Input {
    /// The tracks file.
    pub(crate) tracks_file: String,
    /// `csv`, `geojson` or `ais`.
    pub(crate) tracks_format: String,
    /// The scenario file given with `--scenario` (`null`: synthesized).
    pub(crate) scenario_file: Option<String>,
    /// Ownship's name.
    pub(crate) ownship: String,
    /// The UTC time of second 0 for absolute input times (ISO 8601), else `null`.
    pub(crate) start_time: Option<String>,
    /// The common clock.
    pub(crate) clock: Clock,
    /// The gap limit, seconds.
    pub(crate) max_gap_s: f64,
    /// Stretches longer than the gap limit without a fix: bridged by
    /// straight lines, or dead-reckoned before a target's first fix and
    /// after its last (decision 48).
    pub(crate) gaps: Vec<Gap>,
    /// Ownship reached its goal if it came this close, metres.
    pub(crate) goal_tolerance_m: f64,
    /// Every judged vessel, ownship first.
    pub(crate) vessels: Vec<VesselInput>,
    /// Vessels of the tracks or the scenario that were not judged, and why.
    pub(crate) left_out: Vec<String>,
    /// The defaults the judgement rests on, in words.
    pub(crate) assumptions: Vec<String>,
    /// What the readers skipped.
    pub(crate) notes: Vec<String>,
    /// Every judged vessel as observed (jumps, jitter, status), ownship first.
    pub(crate) observation: Vec<VesselObservation>,
}

/// A run rebuilt from tracks, ready for `vorrt_scenarios::evaluate`.
#[derive(Debug, Clone)]
pub(crate) struct Rebuilt {
    /// The scenario judged against.
    pub(crate) scenario: Scenario,
    /// The tracks as a run.
    pub(crate) record: SimulationRecord,
    /// How they were read.
    pub(crate) input: Input,
}

fn bad(what: String) -> CliError {
    CliError::BadInput(what)
}

/// Whether `track` is the scenario's vessel `spec`: the same MMSI when both
/// give one, else the same name.
fn is_vessel(track: &Track, spec: &VesselSpec) -> bool {
    match (track.mmsi, spec.mmsi) {
        (Some(a), Some(b)) => a == b,
        _ => track.name == spec.name,
    }
}

fn names(tracks: &[Track]) -> String {
    tracks
        .iter()
        .map(|track| format!("{:?}", track.name))
        .collect::<Vec<_>>()
        .join(", ")
}

/// Which track is ownship: `--ownship` (a name or an MMSI), else the
/// scenario's ownship, else the one the file marks, else the first.
fn ownship_index(
    tracks: &[Track],
    options: &Options,
    scenario: Option<&Scenario>,
    assumptions: &mut Vec<String>,
) -> Result<usize, CliError> {
    if let Some(wanted) = &options.ownship {
        let mmsi = wanted.trim().parse::<u32>().ok();
        return tracks
            .iter()
            .position(|track| track.name == *wanted || (mmsi.is_some() && track.mmsi == mmsi))
            .ok_or_else(|| {
                bad(format!(
                    "{}: --ownship {wanted:?} is not among the vessels: {}",
                    options.tracks_file,
                    names(tracks)
                ))
            });
    }
    if let Some(scenario) = scenario
        && let Some(index) = tracks.iter().position(|t| is_vessel(t, &scenario.ownship))
    {
        return Ok(index);
    }
    let (index, why) = match tracks.iter().position(|track| track.marked_ownship) {
        Some(index) => (index, "the vessel the file marks as ownship"),
        None => (0, "the first vessel in the file"),
    };
    let name = tracks.get(index).map_or("", |track| track.name.as_str());
    assumptions.push(format!(
        "ownship is {name:?}, {why}{} (name it with --ownship)",
        scenario.map_or(String::new(), |scenario| format!(
            "; the scenario's ownship {:?} is not among the tracks",
            scenario.ownship.name
        ))
    ));
    Ok(index)
}

/// The targets in judging order: the scenario's in its order, then the
/// other tracks in file order.
fn target_order(tracks: &[Track], own: usize, scenario: Option<&Scenario>) -> Vec<usize> {
    let mut order: Vec<usize> = Vec::new();
    if let Some(scenario) = scenario {
        for spec in &scenario.targets {
            if let Some(index) = tracks.iter().enumerate().position(|(index, t)| {
                index != own && !order.contains(&index) && is_vessel(t, spec)
            }) {
                order.push(index);
            }
        }
    }
    let rest: Vec<usize> = (0..tracks.len())
        .filter(|index| *index != own && !order.contains(index))
        .collect();
    order.extend(rest);
    order
}

/// The local frame for geographic fixes: the scenario's, else one about
/// ownship's first fix.
fn frame_for(
    tracks: &[Track],
    own: usize,
    scenario: Option<&Scenario>,
    options: &Options,
) -> Result<Option<LocalFrame>, CliError> {
    let geographic = tracks
        .iter()
        .flat_map(|track| &track.fixes)
        .any(|fix| matches!(fix.place, Place::LatLon(..)));
    if !geographic {
        return Ok(None);
    }
    if let Some(scenario) = scenario {
        return scenario.local_frame().map(Some).ok_or_else(|| {
            bad(format!(
                "{}: the tracks are in latitude and longitude but the scenario {} is not geographic (no start_lat_lon): judge without --scenario, or give a geographic one",
                options.tracks_file, scenario.source
            ))
        });
    }
    let first = tracks.get(own).and_then(|track| {
        track
            .fixes
            .iter()
            .min_by(|a, b| a.time_s.total_cmp(&b.time_s))
            .map(|fix| fix.place)
    });
    Ok(match first {
        Some(Place::LatLon(lat_deg, lon_deg)) => Some(LocalFrame::new(lat_deg, lon_deg)),
        _ => tracks
            .iter()
            .flat_map(|track| &track.fixes)
            .find_map(|fix| match fix.place {
                Place::LatLon(lat_deg, lon_deg) => Some(LocalFrame::new(lat_deg, lon_deg)),
                Place::Local(_) => None,
            }),
    })
}

/// The judged interval and the judged targets (decision 48): ownship's whole
/// track, and every target observed over at least [`MIN_INTERVAL_FRACTION`]
/// of it (dead-reckoned where it was not observed, [`resample::sample`]); a
/// target observed less is left out, said in `left_out`.
fn interval(
    own: &Prepared,
    targets: &[(usize, Prepared)],
    left_out: &mut Vec<String>,
) -> ((f64, f64), Vec<usize>) {
    let (own_from, own_to) = own.span_s();
    let mut kept = Vec::new();
    for (index, vessel) in targets {
        let (first, last) = vessel.span_s();
        let overlap_s = own_to.min(last) - own_from.max(first);
        if overlap_s >= MIN_INTERVAL_FRACTION * (own_to - own_from) && overlap_s > 0.0 {
            kept.push(*index);
        } else {
            left_out.push(format!(
                "{:?}: observed from {first:.0} s to {last:.0} s, less than {:.0} % of ownship's {own_from:.0} s to {own_to:.0} s",
                vessel.name,
                MIN_INTERVAL_FRACTION * 100.0
            ));
        }
    }
    ((own_from, own_to), kept)
}

/// The scenario's spec of `track` (ownship's when `is_own`).
fn spec_of(scenario: Option<&Scenario>, track: &Track, is_own: bool) -> Option<VesselSpec> {
    let scenario = scenario?;
    if is_own {
        Some(scenario.ownship.clone())
    } else {
        scenario
            .targets
            .iter()
            .find(|spec| is_vessel(track, spec))
            .cloned()
    }
}

fn spec_from(name: &str, sampled: &Sampled, length_m: f64) -> VesselSpec {
    let start = sampled.positions_m.first().copied().unwrap_or(DVec2::ZERO);
    let mut spec = VesselSpec::new(
        name,
        (0.0, 0.0),
        angle::normalize_2pi(sampled.courses_rad.first().copied().unwrap_or(0.0)).to_degrees(),
        units::mps_to_knots(sampled.speeds_mps.first().copied().unwrap_or(0.0)),
        length_m,
    );
    spec.start_nm = None;
    spec.start_m = Some((start.x, start.y));
    spec
}

/// The judged vessels, ownship first: their tracks, their fixes resampled on
/// the common clock, and their lengths in metres.
struct Judged<'a> {
    tracks: Vec<&'a Track>,
    sampled: Vec<Sampled>,
    lengths_m: Vec<f64>,
}

/// Turns `tracks` into a run judged against `scenario` (or a synthesized one).
///
/// # Errors
/// [`CliError::BadInput`] when ownship cannot be found, has too few fixes,
/// the tracks do not overlap, or a setting is invalid.
pub(crate) fn rebuild(
    mut tracks: Tracks,
    scenario: Option<Scenario>,
    options: &Options,
) -> Result<Rebuilt, CliError> {
    let file = options.tracks_file.clone();
    let mut assumptions = Vec::new();
    let mut left_out = Vec::new();
    let start_time = crate::judge::tracks::to_relative_times(&mut tracks);
    let list = &tracks.tracks;
    let own = ownship_index(list, options, scenario.as_ref(), &mut assumptions)?;
    let frame = frame_for(list, own, scenario.as_ref(), options)?;
    let order = target_order(list, own, scenario.as_ref());
    let speed = (file.as_str(), options.max_speed_kn);
    let (own_prepared, prepared, jumps) =
        observation::prepare(list, own, &order, frame.as_ref(), speed)?;
    let (span, kept) = interval(&own_prepared, &prepared, &mut left_out);
    let targets: Vec<&(usize, Prepared)> = prepared
        .iter()
        .filter(|(index, _)| kept.contains(index))
        .collect();
    let mut vessels: Vec<&Prepared> = vec![&own_prepared];
    vessels.extend(targets.iter().map(|(_, vessel)| vessel));
    let clock = resample::clock(&vessels, span, options.step_s)?;
    let gaps: Vec<Gap> = vessels
        .iter()
        .flat_map(|vessel| resample::gaps(vessel, &clock, options.max_gap_s))
        .collect();
    let judged_indexes: Vec<usize> = std::iter::once(own)
        .chain(targets.iter().map(|(index, _)| *index))
        .collect();
    let judged_tracks: Vec<&Track> = judged_indexes.iter().map(|index| &list[*index]).collect();
    let sampled: Vec<Sampled> = vessels
        .iter()
        .map(|vessel| resample::sample(vessel, &clock))
        .collect();
    let (inputs, lengths_m) = vessel_inputs(
        &judged_tracks,
        &vessels,
        &sampled,
        scenario.as_ref(),
        options,
        &mut assumptions,
    );
    let (mut observations, observed) =
        observation::observe_all(list, &judged_indexes, &vessels, &jumps);
    // What each target did not report (decision 49); ownship's own track is
    // what is judged.
    for (observation, vessel) in observations.iter_mut().zip(&vessels).skip(1) {
        observation.unreported = resample::unreported(vessel, &clock, options.max_gap_s);
    }
    let own_length_known = inputs[0].length_from != "default";
    let judged = Judged {
        tracks: judged_tracks,
        sampled,
        lengths_m,
    };
    let scenario_file = scenario.as_ref().map(|scenario| scenario.source.clone());
    let mut scenario = match scenario {
        Some(scenario) => with_judged_targets(scenario, &judged, &mut left_out),
        None => synthesized_scenario(&file, &judged, &clock, start_time.clone(), &mut assumptions)?,
    };
    let (config, max_turn_rate_rad_s) = judging_config(
        &mut scenario,
        &judged,
        (own_length_known, scenario_file.is_some()),
        options,
        &mut assumptions,
    )?;
    let mut record = recorded_run(
        &scenario,
        &clock,
        &judged,
        &config,
        max_turn_rate_rad_s,
        options.goal_tolerance_m,
    );
    record.observations = observations;
    let input = Input {
        tracks_file: file,
        tracks_format: tracks.format.to_owned(),
        scenario_file,
        ownship: list[own].name.clone(),
        start_time,
        clock,
        max_gap_s: options.max_gap_s,
        gaps,
        goal_tolerance_m: options.goal_tolerance_m,
        vessels: inputs,
        left_out,
        assumptions,
        notes: tracks.notes,
        observation: observed,
    };
    Ok(Rebuilt {
        scenario,
        record,
        input,
    })
}

/// Every judged vessel as the input described it, with its length in metres:
/// the scenario's, else the tracks', else the default (an assumption, stated).
fn vessel_inputs(
    tracks: &[&Track],
    vessels: &[&Prepared],
    sampled: &[Sampled],
    scenario: Option<&Scenario>,
    options: &Options,
    assumptions: &mut Vec<String>,
) -> (Vec<VesselInput>, Vec<f64>) {
    let mut inputs = Vec::new();
    let mut vessel_lengths_m = Vec::new();
    for (position, (track, vessel)) in tracks.iter().zip(vessels).enumerate() {
        let (length_m, from) = match (spec_of(scenario, track, position == 0), track.length_m) {
            (Some(spec), _) => (spec.length_m, "scenario"),
            (None, Some(length_m)) => (length_m, "tracks"),
            (None, None) => (options.default_length_m, "default"),
        };
        if from == "default" {
            assumptions.push(format!(
                "{:?} is {length_m} m long (the default; give lengths in the scenario, a `length_m` column or property, or --length-m)",
                track.name
            ));
        }
        let (first_fix_s, last_fix_s) = vessel.span_s();
        let how = |recorded: bool| if recorded { "recorded" } else { "track" }.to_owned();
        inputs.push(VesselInput {
            name: track.name.clone(),
            role: if position == 0 { "ownship" } else { "target" }.into(),
            fixes: vessel.times_s.len(),
            duplicate_times: vessel.duplicates,
            first_fix_s,
            last_fix_s,
            length_m,
            length_from: from.into(),
            courses_from: how(sampled[position].courses_recorded),
            speeds_from: how(sampled[position].speeds_recorded),
        });
        vessel_lengths_m.push(length_m);
    }
    (inputs, vessel_lengths_m)
}

/// The given scenario with the judged targets in track order: each its
/// scenario spec, or one from its track when the scenario lacks it. Both
/// kinds of mismatch are listed in `left_out`.
fn with_judged_targets(
    mut scenario: Scenario,
    judged: &Judged<'_>,
    left_out: &mut Vec<String>,
) -> Scenario {
    let specs: Vec<VesselSpec> = judged
        .tracks
        .iter()
        .enumerate()
        .skip(1)
        .map(|(position, track)| {
            spec_of(Some(&scenario), track, false).unwrap_or_else(|| {
                left_out.push(format!(
                    "{:?}: in the tracks but not in the scenario; judged, starting where its track starts",
                    track.name
                ));
                spec_from(
                    &track.name,
                    &judged.sampled[position],
                    judged.lengths_m[position],
                )
            })
        })
        .collect();
    for spec in &scenario.targets {
        if !specs.iter().any(|kept| kept.name == spec.name) {
            left_out.push(format!(
                "{:?}: in the scenario but not judged (no track of it, or too short)",
                spec.name
            ));
        }
    }
    scenario.targets = specs;
    scenario
}

/// A scenario synthesized from the tracks of `file`: every vessel starts as
/// its first sample, and ownship's goal is the last position of its track.
///
/// # Errors
/// [`CliError::BadInput`] when ownship does not move in the judged interval.
fn synthesized_scenario(
    file: &str,
    judged: &Judged<'_>,
    clock: &Clock,
    start_time: Option<String>,
    assumptions: &mut Vec<String>,
) -> Result<Scenario, CliError> {
    let own_sampled = &judged.sampled[0];
    let mut ownship = spec_from(&judged.tracks[0].name, own_sampled, judged.lengths_m[0]);
    let goal = own_sampled
        .positions_m
        .last()
        .copied()
        .unwrap_or(DVec2::ZERO);
    ownship.goal_m = Some((goal.x, goal.y));
    if ownship.speed_kn <= 0.0 {
        // Stopped at the first sample: its mean speed over the interval.
        let duration_s = clock.to_s - clock.from_s;
        let length_m: f64 = own_sampled
            .positions_m
            .windows(2)
            .map(|pair| pair[0].distance(pair[1]))
            .sum();
        ownship.speed_kn = units::mps_to_knots(length_m / duration_s);
    }
    if !(ownship.speed_kn.is_finite() && ownship.speed_kn > 0.0) {
        return Err(bad(format!(
            "{file}: ownship {:?} does not move in the judged interval",
            ownship.name
        )));
    }
    assumptions.push(format!(
        "no --scenario: ownship's goal is the last position of its track ({:.0} m E, {:.0} m N); its start, course and speed are those of its first sample",
        goal.x, goal.y
    ));
    let targets = judged
        .tracks
        .iter()
        .enumerate()
        .skip(1)
        .map(|(position, track)| {
            spec_from(
                &track.name,
                &judged.sampled[position],
                judged.lengths_m[position],
            )
        })
        .collect();
    let name = std::path::Path::new(file).file_stem().map_or_else(
        || "tracks".to_owned(),
        |stem| stem.to_string_lossy().into_owned(),
    );
    Ok(Scenario {
        name,
        description: Some(format!("synthesized by vorrt judge from {file}")),
        targets,
        start_time,
        source: format!("{file} (scenario synthesized by vorrt judge)"),
        ..Scenario::new(String::new(), ownship)
    })
}

/// The planner configuration the tracks are judged with (`--d-th` applied to
/// `scenario` first) and ownship's rate-of-turn limit, radians per second
/// (`--max-turn-rate-deg-s`, else the given scenario's, the limit ownship
/// sailed under, else from its length where known:
/// [`observation::turn_rate_limit`]).
///
/// # Errors
/// [`CliError::BadInput`] when the scenario's planner settings are invalid.
fn judging_config(
    scenario: &mut Scenario,
    judged: &Judged<'_>,
    (own_length_known, scenario_given): (bool, bool),
    options: &Options,
    assumptions: &mut Vec<String>,
) -> Result<(PlannerConfig, Option<f64>), CliError> {
    if let Some(d_th_m) = options.d_th_m {
        scenario.planner.clearance_m = Some(d_th_m);
    }
    let mut config = scenario
        .planner_config()
        .map_err(|error| bad(error.to_string()))?;
    if options.d_th_m.is_none() && scenario.planner.clearance_m.is_none() {
        assumptions.push(format!(
            "d_th is {} m (the default; set it with --d-th or the scenario's planner.clearance_m)",
            config.clearance_m
        ));
    }
    if let Some(sea_room_m) = options.sea_room_m {
        config.rules.risk_distance.sea_room_m = Some(sea_room_m);
    }
    assumptions.push(super::risk::risk_distance_said(
        &config.rules,
        judged.lengths_m[0],
        &judged.lengths_m[1..],
    ));
    let largest_speed_mps = judged.sampled[0]
        .speeds_mps
        .iter()
        .copied()
        .fold(0.0, f64::max);
    let scenario_rate_deg_s = scenario_given
        .then(|| {
            config
                .turning
                .max_turn_rate_rad_s(scenario.ownship.length_m, scenario.ownship.speed_mps())
        })
        .flatten()
        .map(f64::to_degrees);
    let (max_turn_rate_rad_s, said) = observation::turn_rate_limit(
        options.max_turn_rate_deg_s.or(scenario_rate_deg_s),
        judged.lengths_m[0],
        own_length_known,
        largest_speed_mps,
    );
    assumptions.push(said);
    Ok((config, max_turn_rate_rad_s))
}

/// A vessel's resampled track as states on the clock.
fn vessel_states(sampled: &Sampled, length_m: f64) -> Vec<VesselState> {
    sampled
        .positions_m
        .iter()
        .zip(&sampled.courses_rad)
        .zip(&sampled.speeds_mps)
        .map(|((position, course), speed)| VesselState::new(*position, *course, *speed, length_m))
        .collect()
}

/// The judged tracks as a run with no planner calls. Ownship reached its goal
/// at the first sample of its nearest approach to it, if that came within
/// `goal_tolerance_m`.
fn recorded_run(
    scenario: &Scenario,
    clock: &Clock,
    judged: &Judged<'_>,
    config: &PlannerConfig,
    max_turn_rate_rad_s: Option<f64>,
    goal_tolerance_m: f64,
) -> SimulationRecord {
    let goal_m = scenario.ownship_goal_m();
    let nearest = clock
        .times_s
        .iter()
        .zip(&judged.sampled[0].positions_m)
        .map(|(time_s, position)| (position.distance(goal_m), *time_s))
        .min_by(|a, b| a.0.total_cmp(&b.0));
    let arrival_time_s = nearest
        .filter(|(distance_m, _)| *distance_m <= goal_tolerance_m)
        .map(|(_, time_s)| time_s);
    SimulationRecord {
        scenario: scenario.name.clone(),
        seed: 0,
        time_step_s: clock.step_s,
        times_s: clock.times_s.clone(),
        ownship: vessel_states(&judged.sampled[0], judged.lengths_m[0]),
        target_names: judged
            .tracks
            .iter()
            .skip(1)
            .map(|track| track.name.clone())
            .collect(),
        targets: judged
            .sampled
            .iter()
            .zip(&judged.lengths_m)
            .skip(1)
            .map(|(sampled, length_m)| vessel_states(sampled, *length_m))
            .collect(),
        plans: Vec::new(),
        plans_kept: Vec::new(),
        config: *config,
        max_turn_rate_rad_s,
        observations: Vec::new(),
        reached_goal: arrival_time_s.is_some(),
        arrival_time_s,
    }
}
