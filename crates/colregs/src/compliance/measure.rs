//! What ownship did in a recorded encounter, measured before anything is
//! judged: the closest approach, the window in which the encounter was in
//! force, and the action taken in it (see the measurement list in the
//! [module documentation](super)).

use super::episodes::turn_episodes;
use super::{EncounterSample, ScoringParameters};
use crate::latch::{EncounterLatch, has_passed};
use crate::parameters::RuleParameters;
use crate::passing::PassingSide;
use crate::rules::{
    STEADY_TURN_RATE_RAD_S, course_change_rad, in_contact, is_alteration_eased_back,
    is_detectable_turn, is_measured_readily_apparent, keeps_clearance,
};
use crate::vessel::VesselState;
use glam::DVec2;
use std::f64::consts::PI;
use vorrt_geometry::{angle, closest_point_of_approach, cpa::cpa_clamped, cross};

/// Where in the recording the encounter was in force: `samples[start..end]`,
/// and the sample at which the vessels had passed (`end`, if they did).
#[derive(Debug, Clone, Copy)]
pub(super) struct InForce {
    /// The first sample at or after the latch time.
    pub(super) start: usize,
    /// One past the last in-force sample.
    pub(super) end: usize,
    /// The first sample at which the vessels had passed.
    pub(super) passed_index: Option<usize>,
}

impl InForce {
    /// From the first sample at or after the latch time up to (not including)
    /// the first sample at which the vessels have passed.
    ///
    /// Passed is judged on the course ownship was steering when it got there
    /// (the previous sample's course and speed): a turn made once the vessels
    /// have passed is not a manoeuvre for this encounter, as a bridge officer
    /// resumes course only after judging the other vessel passed. The planner
    /// judges it the same way, at each node on the course that led there.
    pub(super) fn of(
        samples: &[EncounterSample],
        latch: &EncounterLatch,
        parameters: &RuleParameters,
    ) -> Self {
        let start = samples
            .iter()
            .position(|s| s.time_s >= latch.latched_at_s - 1e-9)
            .unwrap_or(samples.len());
        let passed_index = (start..samples.len()).find(|&index| {
            let sample = &samples[index];
            let steering = index
                .checked_sub(1)
                .map_or(&sample.own, |previous| &samples[previous].own);
            let own = VesselState {
                course_rad: steering.course_rad,
                speed_mps: steering.speed_mps,
                ..sample.own
            };
            has_passed(&own, &sample.target, latch.encounter, parameters)
        });
        let end = passed_index.unwrap_or(samples.len());
        Self {
            start,
            end,
            passed_index,
        }
    }

    /// The in-force samples.
    pub(super) fn samples<'a>(&self, samples: &'a [EncounterSample]) -> &'a [EncounterSample] {
        &samples[self.start..self.end]
    }

    /// The in-force samples and the one that ends the window: every step
    /// taken while in force.
    pub(super) fn segments<'a>(&self, samples: &'a [EncounterSample]) -> &'a [EncounterSample] {
        let segment_end = (self.end + 1).min(samples.len());
        &samples[self.start.min(segment_end)..segment_end]
    }
}

/// The signed course change of a sample from the latch's reference course.
pub(super) fn turn_of(latch: &EncounterLatch, sample: &EncounterSample) -> f64 {
    course_change_rad(latch.reference_course_rad, sample.own.course_rad)
}

/// The signed speed change of a sample from the latch's reference speed.
pub(super) fn speed_change_of(latch: &EncounterLatch, sample: &EncounterSample) -> f64 {
    sample.own.speed_mps - latch.reference_speed_mps
}

/// Every measurement of one recorded encounter.
#[derive(Debug, Clone, Copy)]
pub(super) struct Measurements {
    /// Minimum range over the whole run (`+∞` with no samples).
    pub(super) min_distance_m: f64,
    /// When it occurred (the latch time with no samples).
    pub(super) time_of_min_s: f64,
    /// Whether the hulls touched at the closest approach ([`in_contact`]).
    pub(super) in_contact: bool,
    /// Whether `d_th` was kept between the hulls ([`keeps_clearance`]).
    pub(super) clearance_kept: bool,
    /// Side of ownship on which the target lay at the closest approach.
    pub(super) passing_side: Option<PassingSide>,
    /// Range at the first in-force sample.
    pub(super) latch_range_m: Option<f64>,
    /// CPA predicted at the first in-force sample, both holding their velocities.
    pub(super) latch_cpa_m: Option<f64>,
    /// When the action began.
    pub(super) action_time_s: Option<f64>,
    /// Range when the action began.
    pub(super) action_range_m: Option<f64>,
    /// The first course change of at least the action detection threshold
    /// while in force.
    pub(super) first_turn_rad: Option<f64>,
    /// The largest course change while in force up to the closest approach,
    /// signed.
    pub(super) max_course_change_rad: f64,
    /// The largest speed change while in force up to the closest approach,
    /// signed.
    pub(super) max_speed_change_mps: f64,
    /// The largest speed reduction while in force up to the closest
    /// approach, m/s (0 for none).
    pub(super) max_speed_reduction_mps: f64,
    /// Alteration episodes while in force that were detectable but not
    /// readily apparent (rule 8(b)).
    pub(super) small_alterations: usize,
    /// The course change (or, for an alteration of speed, the speed change)
    /// a readily apparent alteration was eased back to before the closest
    /// approach; `None` if held.
    pub(super) eased_back: Option<EasedBack>,
    /// The smallest distance ahead of the target's bow at which ownship
    /// crossed its heading line while in force, within
    /// `crossed_ahead_range_m` and for a real change of side.
    pub(super) crossed_ahead_distance_m: Option<f64>,
    /// Whether the pass predicted at the first in-force sample would break
    /// `d_th`, so that a give-way action was required (decision 42).
    pub(super) action_required: bool,
}

/// How a readily apparent alteration was eased back before the closest
/// approach.
#[derive(Debug, Clone, Copy)]
pub(super) enum EasedBack {
    /// The course change eased back to, radians.
    Course(f64),
    /// The speed change eased back to, m/s.
    Speed(f64),
}

/// Whether a sample shows that the give-way action has begun: the course
/// differs from the reference by at least `action_detection_rad`, or the
/// speed has dropped by at least `action_speed_drop_fraction` of the
/// reference speed.
fn action_begun(
    latch: &EncounterLatch,
    sample: &EncounterSample,
    scoring: &ScoringParameters,
) -> bool {
    turn_of(latch, sample).abs() >= scoring.action_detection_rad
        || -speed_change_of(latch, sample)
            >= scoring.action_speed_drop_fraction * latch.reference_speed_mps
}

impl Measurements {
    /// Measures a recording whose in-force window is `window`.
    pub(super) fn of(
        samples: &[EncounterSample],
        window: &InForce,
        latch: &EncounterLatch,
        parameters: &RuleParameters,
        scoring: &ScoringParameters,
    ) -> Self {
        let (min_distance_m, time_of_min_s, in_contact, clearance_kept, passing_side) =
            match closest_approach(samples, scoring.clearance_m) {
                Some(closest) => (
                    closest.distance_m,
                    closest.time_s,
                    closest.in_contact,
                    closest.clearance_kept,
                    side_at(samples, closest.step, closest.time_s),
                ),
                None => (f64::INFINITY, latch.latched_at_s, false, true, None),
            };
        let in_force = window.samples(samples);
        let latch_sample = in_force.first();
        let latch_cpa_m = latch_sample.map(|s| {
            closest_point_of_approach(
                s.own.position_m,
                s.own.velocity_mps(),
                s.target.position_m,
                s.target.velocity_mps(),
            )
            .distance_m
        });
        let action = in_force.iter().find(|s| action_begun(latch, s, scoring));
        let first_turn_rad = in_force
            .iter()
            .map(|s| turn_of(latch, s))
            .find(|turn| turn.abs() >= scoring.action_detection_rad);
        let before_cpa_count = in_force.partition_point(|s| s.time_s <= time_of_min_s + 1e-9);
        let before_cpa = &in_force[..before_cpa_count];
        let shown = shown_samples(
            samples,
            window,
            (in_force, before_cpa),
            latch,
            time_of_min_s,
            scoring,
        );
        let courses: Vec<f64> = std::iter::once(latch.reference_course_rad)
            .chain(in_force.iter().map(|s| s.own.course_rad))
            .collect();
        let small_alterations = turn_episodes(&courses, parameters)
            .iter()
            .filter(|episode| {
                is_detectable_turn(episode.change_rad, parameters)
                    && !is_measured_readily_apparent(episode.change_rad, parameters)
            })
            .count();
        Self {
            min_distance_m,
            time_of_min_s,
            in_contact,
            clearance_kept,
            passing_side,
            latch_range_m: latch_sample.map(EncounterSample::range_m),
            latch_cpa_m,
            action_time_s: action.map(|s| s.time_s),
            action_range_m: action.map(EncounterSample::range_m),
            first_turn_rad,
            max_course_change_rad: largest_signed(shown.iter().map(|s| turn_of(latch, s))),
            max_speed_change_mps: largest_signed(shown.iter().map(|s| speed_change_of(latch, s))),
            max_speed_reduction_mps: shown
                .iter()
                .map(|s| -speed_change_of(latch, s))
                .fold(0.0, f64::max),
            small_alterations,
            eased_back: eased_back(before_cpa, latch, parameters, scoring),
            crossed_ahead_distance_m: crossing_ahead_distance(samples, window, parameters, scoring),
            action_required: action_required(latch_sample, latch, scoring),
        }
    }
}

/// The samples that show the alteration made while in force, as it shows
/// over ground (`Measurements::of`): from the latch to the closest
/// approach (`before_cpa`, the in-force samples up to it), and through a
/// turn still under way there.
fn shown_samples<'s>(
    samples: &'s [EncounterSample],
    window: &InForce,
    (in_force, before_cpa): (&'s [EncounterSample], &'s [EncounterSample]),
    latch: &EncounterLatch,
    time_of_min_s: f64,
    scoring: &ScoringParameters,
) -> &'s [EncounterSample] {
    let before_cpa_count = before_cpa.len();
    // The alteration made while in force, as it shows over ground: an
    // observer sees a turn begun just before the encounter ended (say by
    // opening the range) up to one reaction time (an observation window)
    // later; never past the closest approach.
    let shown_until_s = in_force
        .last()
        .map_or(f64::NEG_INFINITY, |s| s.time_s + scoring.reaction_time_s)
        .min(time_of_min_s);
    let shown = match window.start {
        start if start < samples.len() && before_cpa_count == in_force.len() => {
            let count = samples[start..].partition_point(|s| s.time_s <= shown_until_s + 1e-9);
            &samples[start..start + count.max(before_cpa_count)]
        }
        _ => before_cpa,
    };
    // A turn under way where the showing ends (at the closest approach)
    // is shown to its end, up to one reaction time later: an alteration
    // begun at once at the rate of turn, for a vessel whose range opens
    // part way round it (a vessel overtaken from close, its closest
    // approach 60-100 s after the latch), is the whole alteration an
    // observer sees made, not the part reached when the range began to
    // open (decision 51).
    match window.start {
        start if start < samples.len() => {
            let count = through_the_turn(
                samples,
                latch,
                start,
                shown.len(),
                time_of_min_s + scoring.reaction_time_s,
            );
            &samples[start..start + count]
        }
        _ => shown,
    }
}

/// How many samples from `start` show the alteration: the first `count`,
/// and after them those of a turn under way at the last of them that
/// enlarges the alteration from `latch`'s reference (each step turning the
/// way the alteration then lies, faster than [`STEADY_TURN_RATE_RAD_S`], the
/// rate of a course held steady), up to `until_s`. A turn back toward the
/// reference (a return begun before the closest approach) adds nothing.
fn through_the_turn(
    samples: &[EncounterSample],
    latch: &EncounterLatch,
    start: usize,
    count: usize,
    until_s: f64,
) -> usize {
    let mut end = start + count;
    let turn_rad = |index: usize| {
        let step_s = samples[index].time_s - samples[index - 1].time_s;
        let turn = angle::signed_turn(
            samples[index - 1].own.course_rad,
            samples[index].own.course_rad,
        );
        if turn.abs() > STEADY_TURN_RATE_RAD_S * step_s + 1e-9 {
            turn
        } else {
            0.0
        }
    };
    if count < 2 || end > samples.len() {
        return count;
    }
    let turning_rad = turn_rad(end - 1);
    if turning_rad == 0.0 {
        return count;
    }
    let direction = turning_rad.signum();
    if turn_of(latch, &samples[end - 1]) * direction <= 0.0 {
        return count;
    }
    while end < samples.len()
        && samples[end].time_s <= until_s + 1e-9
        && turn_rad(end) * direction > 0.0
    {
        end += 1;
    }
    end - start
}

/// Whether a readily apparent alteration, once reached, was eased back
/// before the closest approach (`before_cpa`: the in-force samples up to
/// it). A course alteration is eased back when the course change in its
/// direction falls more than the turn tolerance (2°, not detectable) below
/// the readily apparent one; a speed alteration when the speed reduction
/// falls more than the stand-on speed tolerance below the readily apparent
/// reduction.
fn eased_back(
    before_cpa: &[EncounterSample],
    latch: &EncounterLatch,
    parameters: &RuleParameters,
    scoring: &ScoringParameters,
) -> Option<EasedBack> {
    if let Some(reached) = before_cpa
        .iter()
        .position(|s| is_measured_readily_apparent(turn_of(latch, s), parameters))
    {
        let side = turn_of(latch, &before_cpa[reached]).signum();
        return before_cpa[reached..]
            .iter()
            .map(|s| turn_of(latch, s))
            .find(|turn| is_alteration_eased_back(side * turn, parameters))
            .map(EasedBack::Course);
    }
    let apparent_reduction_mps =
        scoring.apparent_speed_reduction_fraction * latch.reference_speed_mps;
    let reached = before_cpa
        .iter()
        .position(|s| -speed_change_of(latch, s) >= apparent_reduction_mps)?;
    before_cpa[reached..]
        .iter()
        .map(|s| speed_change_of(latch, s))
        .find(|change| -change < apparent_reduction_mps - parameters.stand_on_speed_tolerance_mps)
        .map(EasedBack::Speed)
}

/// The closest approach over a recorded run and what it means for the hulls:
/// the one closest-approach verdict the scoring ([`Measurements`]) and the
/// judgement as observed (`observed::judge`) both use.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct ClosestApproach {
    /// The minimum range, metres (between samples, from the straight relative
    /// track of each step).
    pub(crate) distance_m: f64,
    /// When it occurred, seconds (the recording's time).
    pub(crate) time_s: f64,
    /// Index of the sample that starts the step holding it.
    pub(crate) step: usize,
    /// Whether the hulls touched ([`in_contact`]), on the lengths at `step`.
    pub(crate) in_contact: bool,
    /// Whether `clearance_m` (`d_th`) was kept between the hulls
    /// ([`keeps_clearance`]), on the lengths at `step`.
    pub(crate) clearance_kept: bool,
}

/// The closest approach over the run, judged against `clearance_m`; `None`
/// with no samples.
pub(crate) fn closest_approach(
    samples: &[EncounterSample],
    clearance_m: f64,
) -> Option<ClosestApproach> {
    let first = samples.first()?;
    let mut best = (first.range_m(), first.time_s, 0);
    for (index, pair) in samples.windows(2).enumerate() {
        let (a, b) = (&pair[0], &pair[1]);
        let step_s = b.time_s - a.time_s;
        let relative_a = a.own.position_m - a.target.position_m;
        let relative_b = b.own.position_m - b.target.position_m;
        let (distance_m, time_s) = if step_s > 0.0 {
            let cpa = cpa_clamped(relative_a, (relative_b - relative_a) / step_s, step_s);
            (cpa.distance_m, a.time_s + cpa.time_s)
        } else {
            (relative_b.length(), b.time_s)
        };
        if distance_m < best.0 {
            best = (distance_m, time_s, index);
        }
    }
    let (distance_m, time_s, step) = best;
    let at = &samples[step];
    let (own_m, target_m) = (at.own.length_m, at.target.length_m);
    Some(ClosestApproach {
        distance_m,
        time_s,
        step,
        in_contact: in_contact(distance_m, own_m, target_m),
        clearance_kept: keeps_clearance(distance_m, own_m, target_m, clearance_m),
    })
}

/// Side of ownship on which the target lies at the closest approach.
fn side_at(samples: &[EncounterSample], index: usize, time_s: f64) -> Option<PassingSide> {
    let a = &samples[index];
    let relative = |sample: &EncounterSample| sample.target.position_m - sample.own.position_m;
    let (line_of_sight, course_rad) = match samples.get(index + 1) {
        Some(b) if b.time_s > a.time_s => {
            let fraction = ((time_s - a.time_s) / (b.time_s - a.time_s)).clamp(0.0, 1.0);
            let course = if fraction >= 1.0 {
                b.own.course_rad
            } else {
                a.own.course_rad
            };
            (relative(a).lerp(relative(b), fraction), course)
        }
        _ => (relative(a), a.own.course_rad),
    };
    if line_of_sight.length() <= 1e-9 {
        return None;
    }
    let bearing = angle::relative_bearing(DVec2::ZERO, course_rad, line_of_sight);
    if bearing > 0.0 && bearing < PI {
        Some(PassingSide::Starboard)
    } else if bearing > PI {
        Some(PassingSide::Port)
    } else {
        None
    }
}

/// The smallest distance ahead of the target's bow at which ownship's
/// relative track crosses the target's heading line while in force (over
/// the window's [`segments`](InForce::segments)), counting only a crossing ahead (rule 15) within `crossed_ahead_range_m`
/// of her bow and with a real change of side (decision 42).
///
/// A real change of side: ownship lay clear of the heading line on the side
/// it came from at some sample at or before the crossing, and clear of it on
/// the other side at some sample after it (the window may end as the
/// vessels pass: the whole recording is read). Clear is farther than the
/// target's half length plus what a heading line uncertain by the
/// detectable change ([`turn_tolerance_rad`](RuleParameters::turn_tolerance_rad))
/// sweeps at that distance ahead: a line drawn from a jittery course
/// crosses a vessel passing well clear ahead without her changing side.
pub(super) fn crossing_ahead_distance(
    samples: &[EncounterSample],
    window: &InForce,
    parameters: &RuleParameters,
    scoring: &ScoringParameters,
) -> Option<f64> {
    // Each sample's signed offset from the target's heading line (none for
    // a target at rest: it has no bow to cross).
    let offsets: Vec<Option<f64>> = samples
        .iter()
        .map(|s| {
            let heading = s.target.velocity_mps().normalize_or_zero();
            let relative = s.own.position_m - s.target.position_m;
            (heading != DVec2::ZERO).then(|| cross(heading, relative))
        })
        .collect();
    let clear_of_line = |ahead_m: f64, length_m: f64| {
        0.5 * length_m + ahead_m.max(0.0) * parameters.turn_tolerance_rad.tan()
    };
    let mut nearest: Option<f64> = None;
    let first = window.start.min(samples.len());
    for (step, pair) in window.segments(samples).windows(2).enumerate() {
        let index = first + step;
        let (a, b) = (&pair[0], &pair[1]);
        let heading = a.target.velocity_mps().normalize_or_zero();
        if heading == DVec2::ZERO {
            continue;
        }
        let relative_a = a.own.position_m - a.target.position_m;
        let relative_b = b.own.position_m - b.target.position_m;
        let offset_a = cross(heading, relative_a);
        let offset_b = cross(heading, relative_b);
        let crosses = (offset_a < 0.0 && offset_b >= 0.0) || (offset_a > 0.0 && offset_b <= 0.0);
        if !crosses {
            continue;
        }
        let fraction = offset_a / (offset_a - offset_b);
        let ahead_m = heading.dot(relative_a.lerp(relative_b, fraction));
        if ahead_m <= 0.0 || ahead_m > scoring.crossed_ahead_range_m {
            continue;
        }
        let margin_m = clear_of_line(ahead_m, a.target.length_m);
        let from = offset_a.signum();
        let was_clear = offsets[..=index]
            .iter()
            .flatten()
            .any(|offset| from * offset > margin_m);
        let became_clear = offsets[index + 1..]
            .iter()
            .flatten()
            .any(|offset| -from * offset > margin_m);
        if was_clear && became_clear {
            nearest = Some(nearest.map_or(ahead_m, |n: f64| n.min(ahead_m)));
        }
    }
    nearest
}

/// Whether a give-way action was required (rule 16, "to keep well clear"):
/// the pass predicted at the first in-force sample, the target holding its
/// velocity and ownship the course and speed the encounter was latched on
/// (`latch`'s reference: the course held before any turn under way, on
/// which risk arose), would not keep the clearance `d_th` between the hulls
/// ([`keeps_clearance`]). A pass predicted to keep it is already clear, and
/// no alteration is demanded of it (decision 42; issue 23: a set-up
/// port-to-port pass at 0.8 nm, an overtaking 0.2 nm off). Predicted on the
/// course steered at that sample instead, an alteration begun before the
/// latch (an early one, decision 73) made its own encounter look clear and
/// owe nothing, not even to be held (decision 75). With no in-force
/// sample, nothing was required.
fn action_required(
    latch_sample: Option<&EncounterSample>,
    latch: &EncounterLatch,
    scoring: &ScoringParameters,
) -> bool {
    latch_sample.is_some_and(|s| {
        let held = VesselState {
            course_rad: latch.reference_course_rad,
            speed_mps: latch.reference_speed_mps,
            ..s.own
        };
        let cpa_m = closest_point_of_approach(
            s.own.position_m,
            held.velocity_mps(),
            s.target.position_m,
            s.target.velocity_mps(),
        )
        .distance_m;
        !keeps_clearance(
            cpa_m,
            s.own.length_m,
            s.target.length_m,
            scoring.clearance_m,
        )
    })
}

/// The signed value of largest magnitude, or 0 for none.
pub(super) fn largest_signed(values: impl Iterator<Item = f64>) -> f64 {
    values.fold(0.0, |best, value| {
        if value.abs() > best.abs() {
            value
        } else {
            best
        }
    })
}
