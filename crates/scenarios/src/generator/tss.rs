//! Crossings of a traffic separation scheme at a chosen traffic density.

use super::random::{behaviour_stream, round_to, run_seed, scenario_stream, uniform, uniform_in};
use super::{GeneratorError, OWNSHIP_LENGTH_M, TargetBehaviour, check_range, planner_for_route};
use crate::scenario::{Lane, Scenario, VesselSpec};
use crate::scheme::SeparationZoneSpec;
use serde::{Deserialize, Serialize};
use vorrt_geometry::units;

/// The direction of traffic in a generated traffic separation scheme.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum TssDirection {
    /// One lane, traffic flowing west (course 270), as `fixtures/paper/tss.ron`.
    #[default]
    Westbound,
    /// One lane, traffic flowing east (course 090).
    Eastbound,
    /// Two lanes with a separation zone between them (the scenario's
    /// `separation_zones`): eastbound to the south, westbound to the north
    /// (each flow keeps the zone on its port side).
    TwoWay,
}

impl TssDirection {
    /// Parses `westbound`, `eastbound` or `two-way`.
    ///
    /// # Errors
    /// The accepted names, when `name` is none of them.
    pub fn from_name(name: &str) -> Result<Self, String> {
        match name {
            "westbound" => Ok(Self::Westbound),
            "eastbound" => Ok(Self::Eastbound),
            "two-way" | "two_way" => Ok(Self::TwoWay),
            other => Err(format!(
                "unknown direction {other:?}: expected westbound, eastbound or two-way"
            )),
        }
    }

    /// The command-line name.
    #[must_use]
    pub fn name(&self) -> &'static str {
        match self {
            Self::Westbound => "westbound",
            Self::Eastbound => "eastbound",
            Self::TwoWay => "two-way",
        }
    }
}

/// A crossing of a traffic separation scheme, like `fixtures/paper/tss.ron`:
/// lanes run east-west centred on north = 0; ownship starts
/// `approach_nm` south of the scheme heading north at 10-15 kn and its goal
/// is as far north of it. Each lane holds a stream of targets at 8-15 kn
/// following the lane at random offsets from its centre line, placed
/// uniformly along the stretch of lane from which a target reaches the
/// crossing line (east = 0) between 5 minutes before ownship enters the lane
/// and 5 minutes after it leaves (if ownship held its course):
/// `targets_per_nm` × that stretch's length targets per lane (at least one).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct TssSpec {
    /// Width of each lane, nautical miles.
    pub lane_width_nm: f64,
    /// Traffic density: targets per nautical mile of lane.
    pub targets_per_nm: f64,
    /// One lane or two.
    pub direction: TssDirection,
    /// How the targets move.
    pub behaviour: TargetBehaviour,
    /// Width of the separation zone between two lanes, nautical miles.
    pub separation_zone_nm: f64,
    /// Distance from ownship's start (and goal) to the scheme, nautical miles.
    pub approach_nm: f64,
    /// Ownship's speed range, knots.
    pub own_speed_kn: (f64, f64),
    /// The targets' speed range, knots.
    pub target_speed_kn: (f64, f64),
}

impl TssSpec {
    /// The defaults (one 1 nm westbound lane, as the paper's) at `targets_per_nm`.
    #[must_use]
    pub fn with_density(targets_per_nm: f64) -> Self {
        Self {
            lane_width_nm: 1.0,
            targets_per_nm,
            direction: TssDirection::Westbound,
            behaviour: TargetBehaviour::Constant,
            separation_zone_nm: 0.5,
            approach_nm: 2.5,
            own_speed_kn: (10.0, 15.0),
            target_speed_kn: (8.0, 15.0),
        }
    }

    /// The same with another behaviour.
    #[must_use]
    pub fn with_behaviour(mut self, behaviour: TargetBehaviour) -> Self {
        self.behaviour = behaviour;
        self
    }

    pub(super) fn check(&self) -> Result<(), GeneratorError> {
        let positive = [
            ("lane_width_nm", self.lane_width_nm, 0.2, 10.0),
            ("targets_per_nm", self.targets_per_nm, 0.0, 20.0),
            ("separation_zone_nm", self.separation_zone_nm, 0.0, 10.0),
            ("approach_nm", self.approach_nm, 0.5, 50.0),
        ];
        for (name, value, min, max) in positive {
            if !(value.is_finite() && value >= min && value <= max) {
                return Err(GeneratorError::InvalidSpec(format!(
                    "{name} is {value}, expected a number in [{min}, {max}]"
                )));
            }
        }
        check_range("own_speed_kn", self.own_speed_kn, 1.0, 40.0)?;
        check_range("target_speed_kn", self.target_speed_kn, 1.0, 40.0)?;
        Ok(())
    }
}

/// The lanes of a TSS specification: (lane, traffic course in degrees,
/// north of its centre line in nautical miles).
fn tss_lanes(spec: &TssSpec, half_length_nm: f64) -> Vec<(Lane, f64)> {
    let lane = |name: &str, centre: f64, westward: bool| {
        let (from, to) = if westward {
            (half_length_nm, -half_length_nm)
        } else {
            (-half_length_nm, half_length_nm)
        };
        (
            Lane::new_nm(name, (from, centre), (to, centre), spec.lane_width_nm),
            if westward { 270.0 } else { 90.0 },
        )
    };
    let offset = 0.5 * (spec.lane_width_nm + spec.separation_zone_nm);
    match spec.direction {
        TssDirection::Westbound => vec![lane("westbound", 0.0, true)],
        TssDirection::Eastbound => vec![lane("eastbound", 0.0, false)],
        TssDirection::TwoWay => vec![
            lane("eastbound", -offset, false),
            lane("westbound", offset, true),
        ],
    }
}

/// How many targets a stretch of lane `length_nm` long carries at `per_nm`:
/// at least one.
#[expect(
    clippy::cast_possible_truncation,
    clippy::cast_sign_loss,
    reason = "a bounded, rounded count of targets; negatives saturate to 0"
)]
fn target_count(per_nm: f64, length_nm: f64) -> usize {
    ((per_nm * length_nm).round() as usize).max(1)
}

/// The separation zone of a two-way scheme: the strip between its lanes,
/// `far_nm` each side of the crossing line (rule 10(e)); none for one lane.
fn separation_zones(spec: &TssSpec, far_nm: f64) -> Vec<SeparationZoneSpec> {
    let half_zone_nm = 0.5 * spec.separation_zone_nm;
    if spec.direction != TssDirection::TwoWay || half_zone_nm <= 0.0 {
        return Vec::new();
    }
    vec![SeparationZoneSpec::new_nm(
        "separation zone",
        vec![
            (-far_nm, -half_zone_nm),
            (far_nm, -half_zone_nm),
            (far_nm, half_zone_nm),
            (-far_nm, half_zone_nm),
        ],
    )]
}

/// Scenario `index` of a TSS batch seeded with `seed` (see [`TssSpec`]); the
/// planner's clearance is 100 m, the paper's in a scheme. Validated.
///
/// # Errors
/// [`GeneratorError::InvalidSpec`] for a bad specification.
pub fn tss(spec: &TssSpec, seed: u64, index: u64) -> Result<Scenario, GeneratorError> {
    spec.check()?;
    let mut rng = scenario_stream(seed, index);
    let mut behaviour_rng = behaviour_stream(seed, index);
    let own_speed_kn = round_to(uniform_in(&mut rng, spec.own_speed_kn), 1);
    let scheme_half_nm = match spec.direction {
        TssDirection::TwoWay => spec.lane_width_nm + 0.5 * spec.separation_zone_nm,
        _ => 0.5 * spec.lane_width_nm,
    };
    let start_north = -(scheme_half_nm + spec.approach_nm);
    let ownship = VesselSpec::new(
        "ownship",
        (0.0, start_north),
        0.0,
        own_speed_kn,
        OWNSHIP_LENGTH_M,
    )
    .with_goal_nm((0.0, -start_north));
    let (slowest, fastest) = spec.target_speed_kn;
    // Stretches of lane per lane, from the crossing line upstream.
    let own_hours = |north_nm: f64| (north_nm - start_north) / own_speed_kn;
    let lanes_unsized = tss_lanes(spec, 1.0);
    let stretches: Vec<(f64, f64)> = lanes_unsized
        .iter()
        .map(|(lane, _)| {
            let centre = lane.from_nm.map_or(0.0, |(_, north)| north);
            let enter_h = own_hours(centre - 0.5 * spec.lane_width_nm) - 5.0 / 60.0;
            let leave_h = own_hours(centre + 0.5 * spec.lane_width_nm) + 5.0 / 60.0;
            (slowest * enter_h.max(0.0), fastest * leave_h)
        })
        .collect();
    let far_nm = stretches
        .iter()
        .map(|(_, far)| *far)
        .fold(0.0, f64::max)
        .ceil()
        + 2.0;
    let lanes = tss_lanes(spec, far_nm);
    let mut targets = Vec::new();
    for ((lane, course_deg), (near, far)) in lanes.iter().zip(&stretches) {
        let count = target_count(spec.targets_per_nm, far - near);
        let centre = lane.from_nm.map_or(0.0, |(_, north)| north);
        #[expect(clippy::float_cmp, reason = "courses are the literals 90 and 270")]
        let westward = *course_deg == 270.0;
        let half = (0.5 * spec.lane_width_nm - 0.05).max(0.0);
        for _ in 0..count {
            let speed_kn = round_to(uniform(&mut rng, slowest, fastest), 1);
            let upstream_nm = round_to(uniform(&mut rng, *near, *far), 3);
            let north = round_to(centre + uniform(&mut rng, -half, half), 3);
            let length_m = uniform(&mut rng, 50.0, 200.0).round();
            let (east, goal_east) = if westward {
                (upstream_nm, -far_nm)
            } else {
                (-upstream_nm, far_nm)
            };
            let behaviour = spec
                .behaviour
                .behaviour(&mut behaviour_rng, 3600.0 * upstream_nm / speed_kn);
            targets.push(
                VesselSpec::new(
                    format!("TS{}", targets.len() + 1),
                    (east, north),
                    *course_deg,
                    speed_kn,
                    length_m,
                )
                .with_goal_nm((goal_east, north))
                .with_behaviour(behaviour),
            );
        }
    }
    let route_m = units::nautical_miles_to_m(2.0 * -start_north);
    let (name, description) = describe(spec, seed, index, lanes.len(), targets.len(), own_speed_kn);
    let mut scenario = Scenario {
        name,
        description: Some(description),
        targets,
        planner: planner_for_route(route_m, Some(100.0)),
        lanes: lanes.into_iter().map(|(lane, _)| lane).collect(),
        separation_zones: separation_zones(spec, far_nm),
        seed: Some(run_seed(seed, index)),
        source: format!("<generated tss seed {seed} index {index}>"),
        ..Scenario::new(String::new(), ownship)
    };
    scenario.validate()?;
    Ok(scenario)
}

/// The name and description of a generated TSS scenario.
fn describe(
    spec: &TssSpec,
    seed: u64,
    index: u64,
    lanes: usize,
    targets: usize,
    own_speed_kn: f64,
) -> (String, String) {
    (
        format!(
            "tss-{}-{}pnm-{}-s{seed}-{index:05}",
            spec.direction.name(),
            spec.targets_per_nm,
            spec.behaviour.name()
        ),
        format!(
            "Generated TSS crossing (seed {seed}, index {index}): {lanes} lane(s) {} nm wide, {} targets/nm, {targets} targets; ownship north at {own_speed_kn} kn; clearance 100 m.",
            spec.lane_width_nm, spec.targets_per_nm,
        ),
    )
}
