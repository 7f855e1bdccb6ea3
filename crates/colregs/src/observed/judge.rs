//! The judgement of a recording as observed: every vessel's course and speed
//! over ground, ownship's path quality, and each target's encounter latched
//! and assessed on the observed states.

use super::noise::{TrackNoise, position_noise_m, track_noise, typical_speed_mps};
use super::observe::{OverGround, over_ground_from, speeds_over_ground_from};
use super::quality::{PathQuality, path_quality};
use super::status::NavigationalStatus;
use super::undecided::{
    Undecided, in_force_window_s, median_step_speed_mps, not_reported, rest_contradicted,
};
use super::{ObservedParameters, RecordedTrack, Recording};
use crate::compliance::measure::closest_approach;
use crate::compliance::{
    ComplianceViolation, Duty, EncounterAssessment, EncounterSample, OtherDuty,
    assess_encounter_acting, first_latch, safety_score, steady_courses_rad,
};
use crate::error::ColregsError;
use crate::latch::{EncounterLatch, update_latch_judged};
use crate::vessel::VesselState;
use serde::{Deserialize, Serialize};

/// A finding about ownship's track as a whole, not about one encounter.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case", tag = "kind")]
pub enum TrackFinding {
    /// The track turns faster than the vessel can
    /// ([`max_turn_rate_rad_s`](ObservedParameters::max_turn_rate_rad_s)):
    /// the track is not one the vessel could have sailed.
    TurnRateExceeded {
        /// The largest rate of turn in the track, degrees per second.
        rate_deg_s: f64,
        /// The vessel's limit, degrees per second.
        limit_deg_s: f64,
    },
}

impl TrackFinding {
    /// A short name in snake case, as used in reports.
    #[must_use]
    pub fn name(&self) -> &'static str {
        match self {
            Self::TurnRateExceeded { .. } => "turn_rate_exceeded",
        }
    }
}

impl std::fmt::Display for TrackFinding {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match *self {
            Self::TurnRateExceeded {
                rate_deg_s,
                limit_deg_s,
            } => write!(
                f,
                "rate of turn {rate_deg_s:.2}°/s above the vessel's limit of {limit_deg_s:.2}°/s"
            ),
        }
    }
}

/// Ownship and one target, judged on the observed states.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ObservedEncounter {
    /// The target's name.
    pub name: String,
    /// The encounter latched on the observed states (`None`: no risk of
    /// collision ever arose).
    pub latch: Option<EncounterLatch>,
    /// Smallest distance between the two over the run, metres (exact between
    /// samples; `+∞` with no samples).
    pub min_distance_m: f64,
    /// When it occurred, seconds.
    pub time_of_min_s: f64,
    /// Whether the hulls touched ([`in_contact`](crate::rules::in_contact)).
    pub collision: bool,
    /// Whether the minimum distance kept the clearance `d_th`.
    pub clearance_kept: bool,
    /// The assessment of the encounter on the observed states (`None` when
    /// no encounter arose).
    pub assessment: Option<EncounterAssessment>,
    /// Every finding, safety findings first (with no encounter, only the
    /// clearance finding if broken).
    pub findings: Vec<ComplianceViolation>,
    /// Safety times every applicable rule score, in `[0, 1]`.
    pub score: f64,
    /// Whether no rule was broken (safety findings do not count).
    pub compliant: bool,
    /// The navigational status the target reported, if any: at anchor,
    /// moored or aground it is judged as a stationary obstacle, on
    /// clearance alone (rule 3(i); decision 32).
    pub status: Option<NavigationalStatus>,
    /// Why the recording cannot decide the encounter, if it cannot: still
    /// closing when the tracks ended (decision 32), a reported rest that
    /// the target's motion contradicts, or a closest approach or in-force
    /// window the target did not report (decision 49). The findings so far
    /// stand; the clearance kept and the passing side are not a verdict.
    pub undecided: Option<Undecided>,
}

/// The judgement of a whole recording as observed.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ObservedJudgement {
    /// Ownship's observed course and speed over ground at every sample.
    pub ownship: Vec<OverGround>,
    /// Ownship's path quality.
    pub path: PathQuality,
    /// Findings about ownship's track as a whole.
    pub track_findings: Vec<TrackFinding>,
    /// Per target, in recording order.
    pub targets: Vec<ObservedEncounter>,
    /// No finding: no track finding and no rule broken in any encounter.
    pub compliant: bool,
    /// Every track's jitter and what the judgement made of it (the window
    /// and thresholds used), ownship first, then the targets in order.
    pub noise: Vec<TrackNoise>,
}

/// Judges a recording on the track as sailed and as observed (see the
/// [module documentation](super)).
///
/// # Errors
/// [`ColregsError::InvalidParameter`] when a parameter is out of range,
/// [`ColregsError::InvalidRecording`] when the recording is malformed.
pub fn judge(
    recording: &Recording,
    parameters: &ObservedParameters,
) -> Result<ObservedJudgement, ColregsError> {
    parameters.validate()?;
    recording.validate()?;
    let times_s = &recording.times_s;
    let noise: Vec<TrackNoise> = std::iter::once(&recording.ownship)
        .chain(&recording.targets)
        .map(|track| noise_of(times_s, track, parameters))
        .collect();
    // Ownship's turns are judged above its own jitter (decision 31).
    let own_parameters = above_noise(parameters, &noise[0]);
    let jittery = |noise: &TrackNoise| noise.window_s > parameters.window_s;
    let ownship = observe(
        times_s,
        &recording.ownship,
        noise[0].window_s,
        jittery(&noise[0]),
    );
    let own_states = observed_states(&recording.ownship, &ownship);
    let courses: Vec<f64> = match &recording.ownship.courses_rad {
        Some(courses) => courses.clone(),
        None => ownship.iter().map(|o| o.course_rad).collect(),
    };
    let path = path_quality(
        times_s,
        &recording.ownship.positions_m,
        &courses,
        &own_parameters.rules,
    );
    let track_findings = parameters
        .max_turn_rate_rad_s
        .map(f64::to_degrees)
        .filter(|limit| path.max_turn_rate_deg_s > limit * (1.0 + 1e-6) + 1e-9)
        .map(|limit_deg_s| TrackFinding::TurnRateExceeded {
            rate_deg_s: path.max_turn_rate_deg_s,
            limit_deg_s,
        })
        .into_iter()
        .collect::<Vec<_>>();
    let samples: Vec<Vec<EncounterSample>> = recording
        .targets
        .iter()
        .zip(&noise[1..])
        .map(|(track, noise)| {
            let observed = observe(times_s, track, noise.window_s, jittery(noise));
            let states = observed_states(track, &observed);
            times_s
                .iter()
                .zip(&own_states)
                .zip(states)
                .map(|((time_s, own), target)| EncounterSample::new(*time_s, *own, target))
                .collect()
        })
        .collect();
    let duties = duties_at(&samples, &recording.targets, &own_parameters);
    let names: Vec<&str> = recording.targets.iter().map(|t| t.name.as_str()).collect();
    let targets: Vec<ObservedEncounter> = recording
        .targets
        .iter()
        .zip(&samples)
        .enumerate()
        .map(|(index, (track, samples))| {
            // The duties toward the other vessels: a vessel's own encounter
            // is judged by its own rule, not excused by itself.
            let others: Vec<Option<OtherDuty>> = duties
                .iter()
                .map(|at| OtherDuty::precedent(at.iter().filter(|d| d.vessel != index)))
                .collect();
            let mut judged = judge_target(track, samples, &others, &own_parameters);
            name_departures(&mut judged, &names);
            judged
        })
        .collect();
    let compliant = track_findings.is_empty() && targets.iter().all(|target| target.compliant);
    Ok(ObservedJudgement {
        ownship,
        path,
        track_findings,
        targets,
        compliant,
        noise,
    })
}

/// A track's jitter (the recording's estimate from the fixes, else one from
/// its positions) and the window and thresholds that keep above it.
fn noise_of(times_s: &[f64], track: &RecordedTrack, parameters: &ObservedParameters) -> TrackNoise {
    let jitter_m = track
        .observation
        .position_noise_m
        .or_else(|| position_noise_m(times_s, &track.positions_m))
        .unwrap_or(0.0);
    // Speeds over the longest window: over a short one, jitter adds speed
    // to a slow vessel and so would lower its course jitter.
    let longest_s = parameters.noise.max_window_s.max(parameters.window_s);
    let speeds = speeds_over_ground_from(
        times_s,
        &track.positions_m,
        longest_s,
        before_start_mps(times_s, track, longest_s, false),
    );
    track_noise(
        jitter_m,
        typical_speed_mps(&speeds),
        parameters.window_s,
        parameters.rules.turn_tolerance_rad,
        parameters.scoring.action_detection_rad,
        &parameters.noise,
    )
}

/// The parameters a track is judged with: its window and its thresholds
/// (equal to the given ones for a track without jitter).
fn above_noise(parameters: &ObservedParameters, noise: &TrackNoise) -> ObservedParameters {
    let mut judged = *parameters;
    judged.window_s = noise.window_s;
    judged.rules.turn_tolerance_rad = noise.turn_tolerance_rad;
    judged.scoring.action_detection_rad = noise.action_detection_rad;
    judged
}

/// The observed course and speed over ground of a track. Before the start
/// the vessel is taken to have been in steady motion: with recorded
/// courses, on its first course, at its first step's speed, or for a track
/// whose jitter lengthened its window (`jittery`), at its first window's
/// mean speed (its first step is jitter as much as motion; decision 31); for a
/// track of positions only, at the velocity of its first window
/// ([`over_ground_from`]).
fn observe(
    times_s: &[f64],
    track: &RecordedTrack,
    window_s: f64,
    jittery: bool,
) -> Vec<OverGround> {
    let before_start_mps = before_start_mps(times_s, track, window_s, jittery);
    over_ground_from(times_s, &track.positions_m, window_s, before_start_mps)
}

/// The velocity a track is taken to have held before its start
/// ([`observe`]).
fn before_start_mps(
    times_s: &[f64],
    track: &RecordedTrack,
    window_s: f64,
    jittery: bool,
) -> Option<vorrt_geometry::DVec2> {
    let first_window = first_window_velocity_mps(times_s, &track.positions_m, window_s);
    match (&track.courses_rad, times_s, track.positions_m.as_slice()) {
        (Some(courses), [t0, t1, ..], [p0, p1, ..]) => courses.first().map(|course| {
            let speed_mps = match first_window {
                Some(velocity) if jittery => velocity.length(),
                _ => p0.distance(*p1) / (t1 - t0),
            };
            vorrt_geometry::angle::velocity(*course, speed_mps)
        }),
        _ => first_window,
    }
}

/// The mean velocity over the first `window_s` of a track (or all of it,
/// if shorter), m/s; `None` with fewer than two samples.
fn first_window_velocity_mps(
    times_s: &[f64],
    positions_m: &[vorrt_geometry::DVec2],
    window_s: f64,
) -> Option<vorrt_geometry::DVec2> {
    let (&t0, &p0) = (times_s.first()?, positions_m.first()?);
    let count = times_s.len().min(positions_m.len());
    if count < 2 {
        return None;
    }
    let end_s = (t0 + window_s).min(times_s[count - 1]);
    let after = times_s[..count]
        .partition_point(|t| *t < end_s)
        .min(count - 1);
    let before = after.saturating_sub(1);
    let (ta, tb) = (times_s[before], times_s[after]);
    let fraction = if tb > ta {
        ((end_s - ta) / (tb - ta)).clamp(0.0, 1.0)
    } else {
        1.0
    };
    let end_m = positions_m[before].lerp(positions_m[after], fraction);
    (end_s > t0).then(|| (end_m - p0) / (end_s - t0))
}

/// The observed states of a track: recorded positions, observed course and
/// speed over ground.
fn observed_states(track: &RecordedTrack, observed: &[OverGround]) -> Vec<VesselState> {
    track
        .positions_m
        .iter()
        .zip(observed)
        .map(|(position_m, over)| {
            VesselState::new(*position_m, over.course_rad, over.speed_mps, track.length_m)
        })
        .collect()
}

/// At each sample, ownship's duties toward the targets then (an encounter
/// in force, latched on the observed states, in which it gives way, or
/// stands on within the action range: [`Duty::of`], the reading of
/// [`acting_for_any`](crate::rules::acting_for_any)): while it has one
/// toward another vessel, it may act for the vessels it stands on for
/// ([`crate::rules::may_act`]; decision 45 names it). A duty is carried one
/// observation window (`window_s`) past its end: the observed COG shows a
/// turn made under it that much later (decision 45).
fn duties_at(
    samples: &[Vec<EncounterSample>],
    tracks: &[RecordedTrack],
    parameters: &ObservedParameters,
) -> Vec<Vec<OtherDuty>> {
    let count = samples.first().map_or(0, Vec::len);
    let mut duties = vec![Vec::new(); count];
    let steady = samples.first().map(|track| steady_courses_rad(track));
    for (vessel, (track, _)) in samples
        .iter()
        .zip(tracks)
        .enumerate()
        .filter(|(_, (_, recorded))| !at_rest(recorded))
    {
        let mut latch = None;
        let mut last: Option<OtherDuty> = None;
        let mut last_at_s = f64::NEG_INFINITY;
        for ((sample, at), steady_course_rad) in track
            .iter()
            .zip(duties.iter_mut())
            .zip(steady.iter().flatten())
        {
            latch = update_latch_judged(
                latch,
                &sample.own,
                *steady_course_rad,
                &sample.target,
                sample.time_s,
                &parameters.rules,
            );
            let range_m = sample.range_m();
            let now = latch.and_then(|latch| {
                Duty::of(&latch, range_m, &parameters.rules).map(|duty| OtherDuty {
                    vessel,
                    encounter: latch.encounter,
                    duty,
                    range_m,
                })
            });
            if now.is_some() {
                (last, last_at_s) = (now, sample.time_s);
            }
            let shown = now.or_else(|| {
                last.filter(|_| sample.time_s - last_at_s <= parameters.window_s)
                    .map(|duty| OtherDuty { range_m, ..duty })
            });
            at.extend(shown);
        }
    }
    duties
}

/// Names the other vessels of a judged encounter's justified stand-on
/// departures.
fn name_departures(judged: &mut ObservedEncounter, names: &[&str]) {
    let departures = judged
        .assessment
        .iter_mut()
        .flat_map(|a| a.stand_on_departures.iter_mut());
    for precedence in departures.filter_map(|d| d.precedence.as_mut()) {
        if let Some(name) = names.get(precedence.vessel) {
            (*name).clone_into(&mut precedence.vessel_name);
        }
    }
}

/// Whether the vessel reported itself not under way (at anchor, moored,
/// aground): a stationary obstacle.
fn at_rest(track: &RecordedTrack) -> bool {
    track
        .observation
        .status
        .is_some_and(NavigationalStatus::is_at_rest)
}

/// Whether the two were still closing at the last sample: the closest
/// approach is the end of the tracks, not a passing.
fn still_closing(samples: &[EncounterSample], time_of_min_s: f64) -> bool {
    match samples {
        [.., before, last] => {
            last.range_m() < before.range_m() && (last.time_s - time_of_min_s).abs() <= 1e-6
        }
        _ => false,
    }
}

/// One target: latched and assessed on the observed states, or, if no risk
/// ever arose or the target is at rest, judged on clearance alone.
fn judge_target(
    track: &RecordedTrack,
    samples: &[EncounterSample],
    duties: &[Option<OtherDuty>],
    parameters: &ObservedParameters,
) -> ObservedEncounter {
    let name = track.name.as_str();
    let status = track.observation.status;
    let times_s: Vec<f64> = samples.iter().map(|s| s.time_s).collect();
    let times_s = times_s.as_slice();
    let scoring = &parameters.scoring;
    let latch = if at_rest(track) {
        None
    } else {
        first_latch(samples, &parameters.rules)
    };
    if let Some(latch) = latch {
        let assessment =
            assess_encounter_acting(samples, &latch, &parameters.rules, scoring, duties);
        let collision = assessment
            .violations
            .iter()
            .any(|v| matches!(v, ComplianceViolation::Collision { .. }));
        let in_force_s = in_force_window_s(samples, latch.latched_at_s, assessment.passed_at_s);
        let undecided = not_reported(
            &track.observation.unreported,
            (assessment.time_of_min_s, assessment.min_distance_m),
            in_force_s,
            median_speed_mps(times_s, track),
            |distance_m| keeps(samples, track, distance_m, scoring.clearance_m),
        )
        .or_else(|| {
            (!collision && still_closing(samples, assessment.time_of_min_s))
                .then_some(Undecided::StillClosing)
        });
        return ObservedEncounter {
            name: name.to_owned(),
            latch: Some(latch),
            min_distance_m: assessment.min_distance_m,
            time_of_min_s: assessment.time_of_min_s,
            collision,
            clearance_kept: assessment.safe,
            findings: assessment.violations.clone(),
            score: assessment.scores.overall,
            compliant: assessment.compliant,
            status,
            undecided,
            assessment: Some(assessment),
        };
    }
    let (min_distance_m, time_of_min_s, collision, clearance_kept) =
        match closest_approach(samples, scoring.clearance_m) {
            Some(closest) => (
                closest.distance_m,
                closest.time_s,
                closest.in_contact,
                closest.clearance_kept,
            ),
            None => (f64::INFINITY, 0.0, false, true),
        };
    // A reported rest her motion contradicts: her duties are not known
    // (decision 49). Else a clearance broken where she did not report rests
    // on invented positions. A vessel at rest needs no reports to be where
    // she is.
    let undecided = rest_contradicted(status, median_speed_mps(times_s, track)).or_else(|| {
        (!clearance_kept && !at_rest(track))
            .then(|| {
                not_reported(
                    &track.observation.unreported,
                    (time_of_min_s, min_distance_m),
                    None,
                    median_speed_mps(times_s, track),
                    |_| false,
                )
            })
            .flatten()
    });
    let findings = clearance_findings(clearance_kept, collision, min_distance_m);
    ObservedEncounter {
        name: name.to_owned(),
        latch: None,
        min_distance_m,
        time_of_min_s,
        collision,
        clearance_kept,
        assessment: None,
        findings,
        score: if collision {
            0.0
        } else {
            safety_score(min_distance_m, scoring)
        },
        compliant: true,
        status,
        undecided,
    }
}

/// The findings of a target judged on clearance alone: `d_th` broken
/// between the hulls, and hull contact.
fn clearance_findings(
    clearance_kept: bool,
    collision: bool,
    min_distance_m: f64,
) -> Vec<ComplianceViolation> {
    let mut findings = Vec::new();
    if !clearance_kept {
        findings.push(ComplianceViolation::ClearanceViolated { min_distance_m });
    }
    if collision {
        findings.push(ComplianceViolation::Collision { min_distance_m });
    }
    findings
}

/// Whether `distance_m` between ownship and the target keeps the clearance
/// between the hulls ([`keeps_clearance`](crate::rules::keeps_clearance)).
fn keeps(
    samples: &[EncounterSample],
    track: &RecordedTrack,
    distance_m: f64,
    clearance_m: f64,
) -> bool {
    let own_length_m = samples.first().map_or(0.0, |s| s.own.length_m);
    crate::rules::keeps_clearance(distance_m, own_length_m, track.length_m, clearance_m)
}

/// A track's median speed over ground: the recording's, from the fixes,
/// else from its positions.
fn median_speed_mps(times_s: &[f64], track: &RecordedTrack) -> f64 {
    track
        .observation
        .median_speed_mps
        .unwrap_or_else(|| median_step_speed_mps(times_s, &track.positions_m))
}
