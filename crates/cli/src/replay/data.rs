//! The replay page's data model: what `replay.html` carries as inline JSON,
//! built from the run record, the evaluation and the report that every
//! other output of the run is written from (decision 35).
//!
//! Positions are in the scenario's local frame (x east, y north, metres;
//! a geographic run's azimuthal equidistant frame, `vorrt_scenarios::geo`),
//! the frame the judgement itself is made in. Tracks are integers,
//! delta-coded ([`Track`]), so that a run with 100 targets stays a few
//! hundred kilobytes.

use crate::replay::findings::{FindingMark, finding_marks};
use crate::replay::graticule::{GraticuleLine, graticule};
use crate::report::{Report, TargetReport};
use serde::{Deserialize, Serialize};
use vorrt_colregs::VesselState;
use vorrt_geometry::{DVec2, angle, units};
use vorrt_scenarios::{Evaluation, Scenario, SimulationRecord};

/// The version of the replay data model; raised on any incompatible change.
pub(crate) const REPLAY_FORMAT_VERSION: u32 = 1;

/// At most this many vessel samples (vessels x kept steps) are written; a
/// longer run keeps every k-th step (and the last), so that the page stays a
/// few hundred kilobytes with 100 targets.
pub(crate) const SAMPLE_BUDGET: usize = 60_000;

/// Hull beam as a fraction of the length, for drawing only: the scenario
/// gives lengths, not beams; 1/6 is a typical length-to-beam ratio of
/// merchant ships (decision 35).
pub(crate) const BEAM_PER_LENGTH: f64 = 1.0 / 6.0;

/// A polygon: its outer ring first, then its holes; each ring a list of
/// `[east_m, north_m]` points in the local frame.
pub(crate) type Polygon = Vec<Vec<[f64; 2]>>;

/// Everything `replay.html` draws.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub(crate) struct ReplayData {
    /// [`REPLAY_FORMAT_VERSION`].
    pub(crate) format_version: u32,
    /// The scenario's name.
    pub(crate) scenario: String,
    /// The scenario's description, if any.
    pub(crate) description: Option<String>,
    /// The scenario file the run was made from.
    pub(crate) scenario_file: String,
    /// The planner seed.
    pub(crate) seed: u64,
    /// The clearance `d_th`, metres: the ring drawn around ownship.
    pub(crate) d_th_m: f64,
    /// The run's outcome, from the report.
    pub(crate) verdict: Verdict,
    /// The recorded time step, seconds.
    pub(crate) time_step_s: f64,
    /// Every `step_stride`-th recorded step is kept (1: all of them); the
    /// last step is always kept.
    pub(crate) step_stride: usize,
    /// The time of every kept step, seconds.
    pub(crate) times_s: Vec<f64>,
    /// Ownship first, then the targets in scenario order.
    pub(crate) vessels: Vec<VesselTrack>,
    /// Ownship's goal `[east_m, north_m]`, if it has one.
    pub(crate) goal_m: Option<[f64; 2]>,
    /// Every finding of the report, each at the moment the evaluation dates it.
    pub(crate) findings: Vec<FindingMark>,
    /// Every planner call: when, why, and whether a plan came back.
    pub(crate) plans: Vec<PlanMark>,
    /// The scenario's traffic lanes (rule 10).
    pub(crate) lanes: Vec<LaneShape>,
    /// Land, as polygons (empty: none in the scenario).
    pub(crate) land: Vec<Polygon>,
    /// No-go areas, as polygons (empty: none).
    pub(crate) no_go: Vec<Polygon>,
    /// Separation zones of a traffic separation scheme, as polygons (empty: none).
    pub(crate) separation_zones: Vec<Polygon>,
    /// The geographic frame of a geographic run (`None`: a local run).
    pub(crate) geo: Option<GeoFrame>,
}

/// The run's outcome, as `report.json` gives it.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[expect(
    clippy::struct_excessive_bools,
    reason = "plain data: the report's yes/no outcome fields"
)]
pub(crate) struct Verdict {
    /// Ownship reached its goal.
    pub(crate) reached_goal: bool,
    /// Two hulls touched.
    pub(crate) collision: bool,
    /// Every target stayed at least `d_th` away.
    pub(crate) clearance_kept: bool,
    /// No COLREGs finding.
    pub(crate) compliant: bool,
    /// Smallest distance to any target, metres (`None` without targets).
    pub(crate) min_distance_m: Option<f64>,
}

/// One vessel's track and, for a target, its encounter.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub(crate) struct VesselTrack {
    /// The vessel's name.
    pub(crate) name: String,
    /// `ownship` or `target`.
    pub(crate) role: String,
    /// Hull length, metres.
    pub(crate) length_m: f64,
    /// Hull beam drawn, metres ([`BEAM_PER_LENGTH`] of the length).
    pub(crate) beam_m: f64,
    /// The target's encounter with ownship (`None` for ownship).
    pub(crate) encounter: Option<EncounterMark>,
    /// The states at the kept steps.
    pub(crate) track: Track,
}

/// A target's encounter with ownship, from the report.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub(crate) struct EncounterMark {
    /// The classification when risk first arose (`head_on`, ..., `none`).
    pub(crate) encounter: String,
    /// Ownship's role: `give_way`, `stand_on` or `none`.
    pub(crate) colregs_role: String,
    /// When risk of collision first arose, seconds (`None`: never).
    pub(crate) risk_time_s: Option<f64>,
    /// The closest approach, metres.
    pub(crate) min_distance_m: f64,
    /// When it occurred, seconds.
    pub(crate) time_of_min_s: f64,
    /// Whether the closest approach kept `d_th`.
    pub(crate) clearance_kept: bool,
    /// Whether ownship obeyed every rule that applied.
    pub(crate) compliant: bool,
    /// The score in `[0, 1]`.
    pub(crate) score: f64,
}

/// A vessel's states at the kept steps, as integers coded by difference:
/// the first value is the value, each next one the change from the one
/// before (so that a steady vessel writes mostly small numbers and zeros).
/// A track may stop before the last kept step (a vessel that left the
/// recording).
#[derive(Debug, Clone, Default, PartialEq, Eq, Serialize, Deserialize)]
pub(crate) struct Track {
    /// East, decimetres.
    pub(crate) east_dm: Vec<i64>,
    /// North, decimetres.
    pub(crate) north_dm: Vec<i64>,
    /// Course, tenths of a degree clockwise from north (the running sum
    /// may leave `[0, 3600)`: read it modulo 3600).
    pub(crate) course_ddeg: Vec<i64>,
    /// Speed, hundredths of a knot.
    pub(crate) speed_ckn: Vec<i64>,
}

/// One planner call.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub(crate) struct PlanMark {
    /// When, seconds.
    pub(crate) time_s: f64,
    /// Why (the report's `trigger`).
    pub(crate) trigger: String,
    /// Whether a plan came back.
    pub(crate) succeeded: bool,
}

/// A traffic lane: its centre line and width, traffic flowing from `from_m`
/// to `to_m`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub(crate) struct LaneShape {
    /// The lane's name.
    pub(crate) name: String,
    /// Upstream end of the centre line `[east_m, north_m]`.
    pub(crate) from_m: [f64; 2],
    /// Downstream end of the centre line `[east_m, north_m]`.
    pub(crate) to_m: [f64; 2],
    /// Full width, metres.
    pub(crate) width_m: f64,
}

/// The geographic frame of a run given in latitude and longitude.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub(crate) struct GeoFrame {
    /// The frame's origin (ownship's start), latitude in degrees.
    pub(crate) origin_lat_deg: f64,
    /// The frame's origin, longitude in degrees.
    pub(crate) origin_lon_deg: f64,
    /// Parallels and meridians, projected into the local frame.
    pub(crate) graticule: Vec<GraticuleLine>,
}

/// Tenths, hundredths...: `value * per_unit` rounded to an integer.
fn quantize(value: f64, per_unit: f64) -> i64 {
    // Positions of a sea area (< 10^7 m) and speeds fit an i64 many times over.
    #[expect(
        clippy::cast_possible_truncation,
        reason = "rounded, and far inside the i64 range for any position, course or speed"
    )]
    let quantized = (value * per_unit).round() as i64;
    quantized
}

/// Codes `values` by difference (see [`Track`]).
fn delta_code(values: impl IntoIterator<Item = i64>) -> Vec<i64> {
    let mut previous = 0;
    values
        .into_iter()
        .map(|value| {
            let delta = value - previous;
            previous = value;
            delta
        })
        .collect()
}

/// The recorded steps kept out of `steps` for `vessels` vessels: every
/// `stride`-th and the last, with the stride that keeps the samples within
/// [`SAMPLE_BUDGET`].
#[must_use]
pub(crate) fn kept_steps(steps: usize, vessels: usize) -> (usize, Vec<usize>) {
    let samples = steps.saturating_mul(vessels.max(1));
    let stride = samples.div_ceil(SAMPLE_BUDGET).max(1);
    let mut kept: Vec<usize> = (0..steps).step_by(stride).collect();
    if let Some(last) = steps.checked_sub(1)
        && kept.last() != Some(&last)
    {
        kept.push(last);
    }
    (stride, kept)
}

/// The track of `states` at the `kept` steps.
#[must_use]
pub(crate) fn track(states: &[VesselState], kept: &[usize]) -> Track {
    let kept: Vec<&VesselState> = kept.iter().filter_map(|&step| states.get(step)).collect();
    Track {
        east_dm: delta_code(kept.iter().map(|s| quantize(s.position_m.x, 10.0))),
        north_dm: delta_code(kept.iter().map(|s| quantize(s.position_m.y, 10.0))),
        course_ddeg: delta_code(
            kept.iter()
                .map(|s| quantize(angle::normalize_2pi(s.course_rad).to_degrees(), 10.0)),
        ),
        speed_ckn: delta_code(
            kept.iter()
                .map(|s| quantize(units::mps_to_knots(s.speed_mps), 100.0)),
        ),
    }
}

fn encounter_mark(target: &TargetReport) -> EncounterMark {
    EncounterMark {
        encounter: target.encounter.clone(),
        colregs_role: target.role.clone(),
        risk_time_s: target.risk_time_s,
        min_distance_m: target.min_distance_m,
        time_of_min_s: target.time_of_min_s,
        clearance_kept: target.clearance_kept,
        compliant: target.compliant,
        score: target.score,
    }
}

/// An area's rings in metres, as the page draws them.
fn area_polygon(area: &vorrt_scenarios::Area) -> Polygon {
    area.rings_m
        .iter()
        .map(|ring| ring.iter().copied().map(point).collect())
        .collect()
}

fn point(position_m: DVec2) -> [f64; 2] {
    [position_m.x, position_m.y]
}

/// The corners of the box around every recorded position.
fn extent(record: &SimulationRecord) -> Option<(DVec2, DVec2)> {
    let mut positions = record
        .ownship
        .iter()
        .chain(record.targets.iter().flatten())
        .map(|state| state.position_m);
    let first = positions.next()?;
    Some(positions.fold((first, first), |(low, high), p| (low.min(p), high.max(p))))
}

impl ReplayData {
    /// The replay of the run of `scenario` recorded in `record`, judged in
    /// `evaluation` and reported in `report`.
    #[must_use]
    pub(crate) fn new(
        scenario: &Scenario,
        record: &SimulationRecord,
        evaluation: &Evaluation,
        report: &Report,
    ) -> Self {
        let (step_stride, kept) = kept_steps(record.times_s.len(), 1 + record.targets.len());
        let ownship = VesselTrack {
            name: scenario.ownship.name.clone(),
            role: "ownship".to_owned(),
            length_m: scenario.ownship.length_m,
            beam_m: scenario.ownship.length_m * BEAM_PER_LENGTH,
            encounter: None,
            track: track(&record.ownship, &kept),
        };
        let targets = record.targets.iter().enumerate().map(|(index, states)| {
            let name = record
                .target_names
                .get(index)
                .or_else(|| scenario.targets.get(index).map(|spec| &spec.name))
                .cloned()
                .unwrap_or_else(|| format!("target {}", index + 1));
            let length_m = scenario.targets.get(index).map_or_else(
                || states.first().map_or(0.0, |state| state.length_m),
                |spec| spec.length_m,
            );
            VesselTrack {
                name,
                role: "target".to_owned(),
                length_m,
                beam_m: length_m * BEAM_PER_LENGTH,
                encounter: report.targets.get(index).map(encounter_mark),
                track: track(states, &kept),
            }
        });
        let geo = scenario.local_frame().and_then(|frame| {
            let (low, high) = extent(record)?;
            let (origin_lat_deg, origin_lon_deg) = frame.origin_lat_lon_deg();
            Some(GeoFrame {
                origin_lat_deg,
                origin_lon_deg,
                graticule: graticule(&frame, low, high),
            })
        });
        Self {
            format_version: REPLAY_FORMAT_VERSION,
            scenario: scenario.name.clone(),
            description: scenario.description.clone(),
            scenario_file: report.scenario_file.clone(),
            seed: report.seed,
            d_th_m: report.d_th_m,
            verdict: Verdict {
                reached_goal: report.reached_goal,
                collision: report.collision,
                clearance_kept: report.clearance_kept,
                compliant: report.compliant,
                min_distance_m: report.min_distance_m,
            },
            time_step_s: record.time_step_s,
            step_stride,
            times_s: kept
                .iter()
                .filter_map(|&step| record.times_s.get(step).copied())
                .collect(),
            vessels: std::iter::once(ownship).chain(targets).collect(),
            goal_m: scenario.ownship.goal_position_m().map(point),
            findings: finding_marks(evaluation, report),
            plans: report
                .plans
                .iter()
                .map(|plan| PlanMark {
                    time_s: plan.time_s,
                    trigger: plan.trigger.clone(),
                    succeeded: plan.succeeded,
                })
                .collect(),
            lanes: scenario
                .lanes
                .iter()
                .map(|lane| LaneShape {
                    name: lane.name.clone(),
                    from_m: point(lane.from_m()),
                    to_m: point(lane.to_m()),
                    width_m: lane.width_m(),
                })
                .collect(),
            // The same polygons the planner kept off and the judge measured
            // (decisions 29, 30), outer ring first then holes.
            land: scenario.land_areas().map(area_polygon).collect(),
            no_go: scenario.no_go.iter().map(area_polygon).collect(),
            separation_zones: scenario
                .separation_zones
                .iter()
                .map(|zone| vec![zone.vertices_in_m().into_iter().map(point).collect()])
                .collect(),
            geo,
        }
    }
}

/// Decodes a [`Track`] column (the running sum of its differences), as
/// the page does.
#[cfg(test)]
#[must_use]
pub(crate) fn decode(column: &[i64]) -> Vec<i64> {
    column
        .iter()
        .scan(0, |sum, delta| {
            *sum += delta;
            Some(*sum)
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_short_run_keeps_every_step() {
        assert_eq!(kept_steps(4, 3), (1, vec![0, 1, 2, 3]));
        assert_eq!(kept_steps(0, 3), (1, vec![]));
    }

    #[test]
    fn a_long_run_with_many_vessels_keeps_every_kth_step_and_the_last() {
        let (stride, kept) = kept_steps(1001, 101);
        assert_eq!(stride, 2);
        assert_eq!(kept.first(), Some(&0));
        assert_eq!(kept.last(), Some(&1000));
        assert!(kept.len() * 101 <= SAMPLE_BUDGET + 101);
        let (stride, kept) = kept_steps(1000, 101);
        assert_eq!(stride, 2);
        assert_eq!(&kept[kept.len() - 2..], [998, 999]);
    }

    #[test]
    fn tracks_are_delta_coded_and_decode_to_the_rounded_states() {
        let states = [
            VesselState::new(DVec2::new(10.04, -3.0), 0.0, 5.0, 100.0),
            VesselState::new(DVec2::new(12.5, -3.0), -0.1, 5.0, 100.0),
            VesselState::new(DVec2::new(15.0, -2.0), 0.2, 4.0, 100.0),
        ];
        let track = track(&states, &[0, 1, 2, 7]);
        assert_eq!(track.east_dm, [100, 25, 25]);
        assert_eq!(decode(&track.east_dm), [100, 125, 150]);
        assert_eq!(decode(&track.north_dm), [-30, -30, -20]);
        // -0.1 rad is 354.3 degrees: courses are written in [0, 360).
        assert_eq!(decode(&track.course_ddeg), [0, 3543, 115]);
        assert_eq!(decode(&track.speed_ckn)[2], 778);
    }

    #[test]
    fn decode_of_nothing_is_nothing() {
        assert!(decode(&[]).is_empty());
    }
}
