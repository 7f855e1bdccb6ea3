//! Rule 10 on a recorded track: each visit of a lane or a separation zone,
//! judged by the same headings the planner keeps ([`LaneHeading`]).

use super::{LaneHeading, Scheme, off_perpendicular_rad};
use glam::DVec2;
use serde::{Deserialize, Serialize};
use vorrt_geometry::angle;

/// The clause of rule 10 a finding is under.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Rule10Clause {
    /// 10(c): a lane crossed on a heading farther from perpendicular to its
    /// flow than the crossing tolerance.
    CrossingNotSquare,
    /// 10(b)(i): in a lane heading against its flow.
    AgainstFlow,
    /// 10(b)(iii): joined or left a lane from the side at more than the
    /// flow tolerance to its flow (and not square across it).
    JoinOrLeaveAngle,
    /// 10(b)(ii), 10(e): in a separation zone other than crossing it square.
    SeparationZone,
}

impl Rule10Clause {
    /// Every clause, in a fixed order.
    pub const ALL: [Rule10Clause; 4] = [
        Rule10Clause::CrossingNotSquare,
        Rule10Clause::AgainstFlow,
        Rule10Clause::JoinOrLeaveAngle,
        Rule10Clause::SeparationZone,
    ];

    /// Its name in files (snake case, as serialised).
    #[must_use]
    pub fn key(self) -> &'static str {
        match self {
            Self::CrossingNotSquare => "rule_10c_crossing_not_square",
            Self::AgainstFlow => "rule_10b_against_flow",
            Self::JoinOrLeaveAngle => "rule_10b_join_leave_angle",
            Self::SeparationZone => "rule_10e_separation_zone",
        }
    }

    /// What it means, for messages.
    #[must_use]
    pub fn description(self) -> &'static str {
        match self {
            Self::CrossingNotSquare => "rule 10(c): crossed a lane not at right angles to its flow",
            Self::AgainstFlow => "rule 10(b)(i): in a lane against its flow",
            Self::JoinOrLeaveAngle => {
                "rule 10(b)(iii): joined or left a lane at a large angle to its flow"
            }
            Self::SeparationZone => "rule 10(e): in a separation zone other than crossing it",
        }
    }
}

/// One finding of rule 10 on a track.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Rule10Finding {
    /// The clause.
    pub clause: Rule10Clause,
    /// The lane's index (the zone's, for [`Rule10Clause::SeparationZone`]).
    pub area: usize,
    /// The first sample of the visit that breaks it, seconds.
    pub start_time_s: f64,
    /// The last, seconds.
    pub end_time_s: f64,
    /// The worst angle: from perpendicular to the flow (10(c), 10(e)), or
    /// the largest from the flow (10(b)(i), 10(b)(iii)), degrees.
    pub worst_angle_deg: f64,
}

impl std::fmt::Display for Rule10Finding {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let what = if self.clause == Rule10Clause::SeparationZone {
            "zone"
        } else {
            "lane"
        };
        write!(
            f,
            "{} ({what} {}, {:.0}-{:.0} s, worst {:.1}°)",
            self.clause.description(),
            self.area,
            self.start_time_s,
            self.end_time_s,
            self.worst_angle_deg
        )
    }
}

/// One crossing of a lane: the track entered it from one side and left by
/// the other.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct LaneCrossing {
    /// The lane's index.
    pub lane: usize,
    /// The first sample inside the lane, seconds.
    pub entry_time_s: f64,
    /// The last, seconds.
    pub exit_time_s: f64,
    /// The largest angle of the heading from perpendicular to the flow
    /// inside the lane, degrees.
    pub max_off_perpendicular_deg: f64,
    /// Whether it stayed within the crossing tolerance (10(c)).
    pub square: bool,
}

/// Rule 10 on one track: the lane crossings and every finding.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct Rule10Judgement {
    /// Every crossing of a lane, in time order per lane.
    pub crossings: Vec<LaneCrossing>,
    /// Every finding, lanes first, then zones.
    pub findings: Vec<Rule10Finding>,
}

impl Rule10Judgement {
    /// Whether no finding was made.
    #[must_use]
    pub fn is_clean(&self) -> bool {
        self.findings.is_empty()
    }

    /// How many crossings stayed within the crossing tolerance.
    #[must_use]
    pub fn square_crossings(&self) -> usize {
        self.crossings.iter().filter(|c| c.square).count()
    }

    /// How many findings are under `clause`.
    #[must_use]
    pub fn count(&self, clause: Rule10Clause) -> usize {
        self.findings.iter().filter(|f| f.clause == clause).count()
    }
}

/// Judges a track under rule 10: `courses_rad[i]` is the heading at
/// `times_s[i]`, `positions_m[i]` (as sailed: the heading; as observed: the
/// course over ground). The three are read to the shortest's length.
///
/// Each run of samples inside a lane is a visit: a **crossing** when the
/// samples before and after it lie on opposite sides of the centre line
/// (its heading is judged against 10(c)), else (a visit at the track's
/// start or end too) a join, a leave or a stretch
/// sailed along it (judged against 10(b)(iii)); a heading against the flow
/// is a 10(b)(i) finding either way. Each run inside a separation zone not
/// square across its axis is a 10(e) finding.
///
/// ```
/// use vorrt_colregs::rule10::{Scheme, TrafficLane, Rule10Clause, judge_track};
/// use glam::DVec2;
/// let scheme = Scheme {
///     lanes: vec![TrafficLane { from_m: DVec2::new(5000.0, 0.0), to_m: DVec2::new(-5000.0, 0.0), width_m: 1000.0 }],
///     ..Scheme::default()
/// };
/// // North-east across a westbound lane: 45° from square.
/// let times: Vec<f64> = (0..60).map(|i| f64::from(i) * 10.0).collect();
/// let course = 45f64.to_radians();
/// let positions: Vec<DVec2> = times.iter().map(|t| DVec2::new(1.0, 1.0) * (t * 5.0 / 2f64.sqrt()) - DVec2::new(0.0, 1000.0)).collect();
/// let judgement = judge_track(&scheme, &times, &positions, &vec![course; 60]);
/// assert_eq!(judgement.crossings.len(), 1);
/// assert_eq!(judgement.count(Rule10Clause::CrossingNotSquare), 1);
/// ```
#[must_use]
pub fn judge_track(
    scheme: &Scheme,
    times_s: &[f64],
    positions_m: &[DVec2],
    courses_rad: &[f64],
) -> Rule10Judgement {
    let count = times_s.len().min(positions_m.len()).min(courses_rad.len());
    let (times_s, positions_m, courses_rad) = (
        &times_s[..count],
        &positions_m[..count],
        &courses_rad[..count],
    );
    let parameters = &scheme.parameters;
    let mut judgement = Rule10Judgement::default();
    for (index, lane) in scheme.lanes.iter().enumerate() {
        let flow_rad = lane.flow_course_rad();
        for (first, last) in runs(count, |i| lane.contains_m(positions_m[i])) {
            let side = |i: usize| lane.lane_coordinates_m(positions_m[i]).1;
            // A visit at either end of the track has no known side to
            // come from or go to: not a crossing.
            let crossing = first > 0 && last + 1 < count && side(first - 1) * side(last + 1) < 0.0;
            let visit = first..=last;
            let finding = |clause, samples: &[usize], worst_angle_rad: f64| Rule10Finding {
                clause,
                area: index,
                start_time_s: times_s[samples[0]],
                end_time_s: times_s[samples[samples.len() - 1]],
                worst_angle_deg: worst_angle_rad.to_degrees(),
            };
            let heading = |i: usize| LaneHeading::of(flow_rad, courses_rad[i], parameters);
            let against: Vec<usize> = visit
                .clone()
                .filter(|&i| heading(i) == LaneHeading::AgainstFlow)
                .collect();
            if !against.is_empty() {
                let worst = against
                    .iter()
                    .map(|&i| angle::signed_turn(flow_rad, courses_rad[i]).abs())
                    .fold(0.0, f64::max);
                judgement
                    .findings
                    .push(finding(Rule10Clause::AgainstFlow, &against, worst));
            }
            if crossing {
                let off = |i: usize| off_perpendicular_rad(flow_rad, courses_rad[i]);
                let worst = visit.clone().map(off).fold(0.0, f64::max);
                let square = worst <= parameters.crossing_tolerance_rad;
                judgement.crossings.push(LaneCrossing {
                    lane: index,
                    entry_time_s: times_s[first],
                    exit_time_s: times_s[last],
                    max_off_perpendicular_deg: worst.to_degrees(),
                    square,
                });
                if !square {
                    let off_square: Vec<usize> = visit
                        .filter(|&i| off(i) > parameters.crossing_tolerance_rad)
                        .collect();
                    judgement.findings.push(finding(
                        Rule10Clause::CrossingNotSquare,
                        &off_square,
                        worst,
                    ));
                }
            } else {
                let oblique: Vec<usize> = visit
                    .filter(|&i| heading(i) == LaneHeading::Oblique)
                    .collect();
                if !oblique.is_empty() {
                    let worst = oblique
                        .iter()
                        .map(|&i| angle::signed_turn(flow_rad, courses_rad[i]).abs())
                        .fold(0.0, f64::max);
                    judgement.findings.push(finding(
                        Rule10Clause::JoinOrLeaveAngle,
                        &oblique,
                        worst,
                    ));
                }
            }
        }
    }
    judge_zones(scheme, times_s, positions_m, courses_rad, &mut judgement);
    judgement
}

/// The 10(e) findings: each run of samples inside a zone with a heading
/// not square across its axis.
fn judge_zones(
    scheme: &Scheme,
    times_s: &[f64],
    positions_m: &[DVec2],
    courses_rad: &[f64],
    judgement: &mut Rule10Judgement,
) {
    let count = times_s.len();
    let parameters = &scheme.parameters;
    for (index, zone) in scheme.zones.iter().enumerate() {
        let off = |i: usize| off_perpendicular_rad(zone.axis_course_rad, courses_rad[i]);
        for (first, last) in runs(count, |i| zone.contains_m(positions_m[i])) {
            let off_square: Vec<usize> = (first..=last)
                .filter(|&i| off(i) > parameters.crossing_tolerance_rad)
                .collect();
            if let (Some(&start), Some(&end)) = (off_square.first(), off_square.last()) {
                judgement.findings.push(Rule10Finding {
                    clause: Rule10Clause::SeparationZone,
                    area: index,
                    start_time_s: times_s[start],
                    end_time_s: times_s[end],
                    worst_angle_deg: off_square
                        .iter()
                        .map(|&i| off(i))
                        .fold(0.0, f64::max)
                        .to_degrees(),
                });
            }
        }
    }
}

/// The maximal runs `(first, last)` of indices below `count` where `inside` holds.
fn runs(count: usize, inside: impl Fn(usize) -> bool) -> Vec<(usize, usize)> {
    let mut runs = Vec::new();
    let mut start = None;
    for i in 0..count {
        match (inside(i), start) {
            (true, None) => start = Some(i),
            (false, Some(first)) => {
                runs.push((first, i - 1));
                start = None;
            }
            _ => {}
        }
    }
    if let Some(first) = start {
        runs.push((first, count - 1));
    }
    runs
}
