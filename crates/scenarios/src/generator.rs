//! Seeded scenario generators for Monte Carlo campaigns: open-sea encounters
//! with a chosen mix of encounter types, and crossings of a traffic
//! separation scheme at a chosen traffic density.
//!
//! Every draw comes from a ChaCha8 stream of its own per scenario index
//! (seed = the batch seed, stream = the index), so scenario `k` of a batch is
//! the same however the batch is sharded, and a behaviour's own draws (when a
//! [`Behaviour::SuddenTurn`] target turns) come from a second stream, so the
//! same seed and index give the same geometry under every behaviour: the
//! behaviours can be compared scenario by scenario.
//!
//! ```
//! use vorrt_scenarios::generator::{OpenSeaSpec, open_sea};
//! let spec = OpenSeaSpec::with_targets(4);
//! let scenario = open_sea(&spec, 7, 0).unwrap();
//! assert_eq!(scenario.targets.len(), 4);
//! assert_eq!(scenario, open_sea(&spec, 7, 0).unwrap()); // deterministic
//! ```

use crate::error::ScenarioError;
use crate::planner_settings::PlannerSettings;
use crate::scenario::{Behaviour, Lane, Scenario, VesselSpec};
use glam::DVec2;
use rand_chacha::ChaCha8Rng;
use rand_core::{RngCore, SeedableRng};
use serde::{Deserialize, Serialize};
use thiserror::Error;
use vorrt_colregs::{Encounter, RuleParameters, VesselState, assess_risk, classify};
use vorrt_geometry::{angle, closest_point_of_approach, units};

/// The most targets an open-sea scenario may be generated with.
pub const MAX_GENERATED_TARGETS: usize = 64;

/// Ownship's length in every generated scenario, metres.
pub const OWNSHIP_LENGTH_M: f64 = 100.0;

/// Why a scenario could not be generated.
#[derive(Debug, Error)]
pub enum GeneratorError {
    /// The specification is unusable (no targets, weights all zero, a range
    /// the wrong way round, ...).
    #[error("invalid generator specification: {0}")]
    InvalidSpec(String),
    /// No placement of a target gave the intended encounter within the
    /// allowed number of draws.
    #[error(
        "scenario {index}: could not place target {target} as a {encounter} encounter in {attempts} draws"
    )]
    Placement {
        /// The scenario index.
        index: u64,
        /// The target's position in the scenario (from 0).
        target: usize,
        /// The intended encounter type.
        encounter: Encounter,
        /// How many draws were tried.
        attempts: usize,
    },
    /// The generated scenario failed validation (a bug in the generator).
    #[error("generated scenario is invalid: {0}")]
    Invalid(#[from] ScenarioError),
}

/// Relative weights of the encounter types of open-sea targets, from
/// ownship's side. Need not sum to 1; at least one must be positive.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct EncounterMix {
    /// Head-on (rule 14).
    pub head_on: f64,
    /// Crossing from starboard: ownship gives way (rule 15).
    pub crossing_give_way: f64,
    /// Crossing from port: ownship stands on (rule 17).
    pub crossing_stand_on: f64,
    /// Ownship overtakes the target (rule 13).
    pub overtaking: f64,
    /// The target overtakes ownship (rules 13, 17).
    pub being_overtaken: f64,
}

impl Default for EncounterMix {
    /// Every type equally likely.
    fn default() -> Self {
        Self {
            head_on: 1.0,
            crossing_give_way: 1.0,
            crossing_stand_on: 1.0,
            overtaking: 1.0,
            being_overtaken: 1.0,
        }
    }
}

impl EncounterMix {
    fn weighted(&self) -> [(Encounter, f64); 5] {
        [
            (Encounter::HeadOn, self.head_on),
            (Encounter::CrossingGiveWay, self.crossing_give_way),
            (Encounter::CrossingStandOn, self.crossing_stand_on),
            (Encounter::Overtaking, self.overtaking),
            (Encounter::BeingOvertaken, self.being_overtaken),
        ]
    }

    fn check(&self) -> Result<(), GeneratorError> {
        let weights = self.weighted();
        if weights
            .iter()
            .any(|(_, weight)| !(weight.is_finite() && *weight >= 0.0))
        {
            return Err(GeneratorError::InvalidSpec(
                "encounter weights must be finite and not negative".into(),
            ));
        }
        if weights.iter().all(|(_, weight)| *weight == 0.0) {
            return Err(GeneratorError::InvalidSpec(
                "at least one encounter weight must be positive".into(),
            ));
        }
        Ok(())
    }

    fn draw(&self, rng: &mut ChaCha8Rng) -> Encounter {
        let weights = self.weighted();
        let total: f64 = weights.iter().map(|(_, weight)| weight).sum();
        let mut pick = uniform(rng, 0.0, total);
        for (encounter, weight) in weights {
            if pick < weight {
                return encounter;
            }
            pick -= weight;
        }
        weights
            .iter()
            .rev()
            .find(|(_, weight)| *weight > 0.0)
            .map_or(Encounter::HeadOn, |(encounter, _)| *encounter)
    }
}

/// How the generated targets move: the [`Behaviour`] every target gets, with
/// the sudden turns drawn per target.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum TargetBehaviour {
    /// [`Behaviour::ConstantToGoal`]: the paper's non-manoeuvring targets.
    #[default]
    Constant,
    /// [`Behaviour::Colregs`]: targets give way to ownship when the rules say so.
    Colregs,
    /// [`Behaviour::Noisy`] with these standard deviations.
    Noisy {
        /// Course noise, degrees.
        course_sigma_deg: f64,
        /// Speed noise, knots.
        speed_sigma_kn: f64,
    },
    /// [`Behaviour::SuddenTurn`]: each target turns 30-90° to a random side
    /// at a random time between 25 % and 75 % of its time to its closest
    /// approach with ownship (open sea) or of its time to the crossing line
    /// (TSS).
    SuddenTurn,
}

/// Default course noise of [`TargetBehaviour::Noisy`], degrees.
pub const DEFAULT_COURSE_SIGMA_DEG: f64 = 5.0;
/// Default speed noise of [`TargetBehaviour::Noisy`], knots.
pub const DEFAULT_SPEED_SIGMA_KN: f64 = 0.5;

impl TargetBehaviour {
    /// Parses a command-line name: `constant`, `colregs`, `noisy` (default
    /// sigmas) or `sudden-turn`.
    ///
    /// # Errors
    /// The accepted names, when `name` is none of them.
    pub fn from_name(name: &str) -> Result<Self, String> {
        match name {
            "constant" => Ok(Self::Constant),
            "colregs" => Ok(Self::Colregs),
            "noisy" => Ok(Self::Noisy {
                course_sigma_deg: DEFAULT_COURSE_SIGMA_DEG,
                speed_sigma_kn: DEFAULT_SPEED_SIGMA_KN,
            }),
            "sudden-turn" | "sudden_turn" => Ok(Self::SuddenTurn),
            other => Err(format!(
                "unknown behaviour {other:?}: expected constant, colregs, noisy or sudden-turn"
            )),
        }
    }

    /// The command-line name.
    #[must_use]
    pub fn name(&self) -> &'static str {
        match self {
            Self::Constant => "constant",
            Self::Colregs => "colregs",
            Self::Noisy { .. } => "noisy",
            Self::SuddenTurn => "sudden-turn",
        }
    }

    /// The behaviour of one target whose event time scale is `time_scale_s`.
    fn behaviour(&self, rng: &mut ChaCha8Rng, time_scale_s: f64) -> Behaviour {
        match *self {
            Self::Constant => Behaviour::ConstantToGoal,
            Self::Colregs => Behaviour::Colregs,
            Self::Noisy {
                course_sigma_deg,
                speed_sigma_kn,
            } => Behaviour::Noisy {
                course_sigma_deg,
                speed_sigma_kn,
            },
            Self::SuddenTurn => {
                let at_s = (uniform(rng, 0.25, 0.75) * time_scale_s).round();
                let side = if rng.next_u64() & 1 == 0 { 1.0 } else { -1.0 };
                let turn_deg = side * uniform(rng, 30.0, 90.0).round();
                Behaviour::SuddenTurn { at_s, turn_deg }
            }
        }
    }
}

/// An open-sea encounter: ownship starts at the origin heading north at
/// 10-15 kn for a goal 8-12 nm ahead, and every target is placed on an almost
/// collision course with it — if both held course, the CPA would be under
/// `max_cpa_nm` (so under the 1 nm risk threshold) in 8-25 minutes — in an
/// encounter of the intended type when risk first arises (checked with
/// `vorrt_colregs::classify`; a draw that misses is redrawn).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct OpenSeaSpec {
    /// Number of targets, 1 to [`MAX_GENERATED_TARGETS`].
    pub targets: usize,
    /// Weights of the encounter types.
    pub mix: EncounterMix,
    /// How the targets move.
    pub behaviour: TargetBehaviour,
    /// Ownship's speed range, knots.
    pub own_speed_kn: (f64, f64),
    /// Range of the distance to ownship's goal, nautical miles.
    pub goal_distance_nm: (f64, f64),
    /// Range of the time to the closest approach, minutes.
    pub tcpa_min: (f64, f64),
    /// Largest CPA distance, nautical miles (under the 1 nm risk threshold).
    pub max_cpa_nm: f64,
    /// Draws allowed per target before giving up.
    pub max_attempts: usize,
}

impl OpenSeaSpec {
    /// The defaults with `targets` targets.
    #[must_use]
    pub fn with_targets(targets: usize) -> Self {
        Self {
            targets,
            mix: EncounterMix::default(),
            behaviour: TargetBehaviour::Constant,
            own_speed_kn: (10.0, 15.0),
            goal_distance_nm: (8.0, 12.0),
            tcpa_min: (8.0, 25.0),
            max_cpa_nm: 0.3,
            max_attempts: 1000,
        }
    }

    /// The same with another behaviour.
    #[must_use]
    pub fn with_behaviour(mut self, behaviour: TargetBehaviour) -> Self {
        self.behaviour = behaviour;
        self
    }

    fn check(&self) -> Result<(), GeneratorError> {
        if !(1..=MAX_GENERATED_TARGETS).contains(&self.targets) {
            return Err(GeneratorError::InvalidSpec(format!(
                "targets is {}, expected 1 to {MAX_GENERATED_TARGETS}",
                self.targets
            )));
        }
        self.mix.check()?;
        check_range("own_speed_kn", self.own_speed_kn, 1.0, 40.0)?;
        check_range("goal_distance_nm", self.goal_distance_nm, 1.0, 100.0)?;
        check_range("tcpa_min", self.tcpa_min, 1.0, 600.0)?;
        if !(self.max_cpa_nm >= 0.0 && self.max_cpa_nm < 1.0) {
            return Err(GeneratorError::InvalidSpec(format!(
                "max_cpa_nm is {}, expected at least 0 and under the 1 nm risk threshold",
                self.max_cpa_nm
            )));
        }
        if self.max_attempts == 0 {
            return Err(GeneratorError::InvalidSpec(
                "max_attempts must be at least 1".into(),
            ));
        }
        Ok(())
    }
}

fn check_range(
    name: &str,
    (low, high): (f64, f64),
    min: f64,
    max: f64,
) -> Result<(), GeneratorError> {
    if low.is_finite() && high.is_finite() && min <= low && low <= high && high <= max {
        Ok(())
    } else {
        Err(GeneratorError::InvalidSpec(format!(
            "{name} is ({low}, {high}), expected low <= high within [{min}, {max}]"
        )))
    }
}

/// The direction of traffic in a generated traffic separation scheme.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum TssDirection {
    /// One lane, traffic flowing west (course 270), as `fixtures/paper/tss.ron`.
    #[default]
    Westbound,
    /// One lane, traffic flowing east (course 090).
    Eastbound,
    /// Two lanes with a separation zone between them: eastbound to the south,
    /// westbound to the north (each flow keeps the zone on its port side).
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

    fn check(&self) -> Result<(), GeneratorError> {
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

/// What to generate: an open-sea encounter or a TSS crossing.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum GeneratorSpec {
    /// [`open_sea`].
    OpenSea(OpenSeaSpec),
    /// [`tss`].
    Tss(TssSpec),
}

impl GeneratorSpec {
    /// Scenario `index` of the batch seeded with `seed`.
    ///
    /// # Errors
    /// As [`open_sea`] and [`tss`].
    pub fn generate(&self, seed: u64, index: u64) -> Result<Scenario, GeneratorError> {
        match self {
            Self::OpenSea(spec) => open_sea(spec, seed, index),
            Self::Tss(spec) => tss(spec, seed, index),
        }
    }
}

/// The random stream of scenario `index` of a batch seeded with `seed`.
#[must_use]
pub fn scenario_stream(seed: u64, index: u64) -> ChaCha8Rng {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    rng.set_stream(index);
    rng
}

/// The stream of a scenario's behaviour draws: separate from its geometry's.
fn behaviour_stream(seed: u64, index: u64) -> ChaCha8Rng {
    let mut rng = ChaCha8Rng::seed_from_u64(seed ^ 0xB3A7_1F0E_5EED_0001);
    rng.set_stream(index);
    rng
}

/// The simulation seed of scenario `index` of a batch seeded with `seed`
/// (SplitMix64 of the two): what the batch runner simulates it with, and what
/// generated scenarios carry in their `seed` field, so that
/// `vorrt simulate` on a generated file repeats its batch run.
#[must_use]
pub fn run_seed(seed: u64, index: u64) -> u64 {
    splitmix64(seed ^ splitmix64(index.wrapping_add(0x5EED)))
}

fn splitmix64(x: u64) -> u64 {
    let mut z = x.wrapping_add(0x9E37_79B9_7F4A_7C15);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

/// A uniform draw in `[low, high)`.
fn uniform(rng: &mut ChaCha8Rng, low: f64, high: f64) -> f64 {
    let unit = (rng.next_u64() >> 11) as f64 / (1u64 << 53) as f64;
    low + (high - low) * unit
}

fn uniform_in(rng: &mut ChaCha8Rng, (low, high): (f64, f64)) -> f64 {
    uniform(rng, low, high)
}

/// Rounds to `digits` decimals so that files stay readable.
fn round_to(value: f64, digits: i32) -> f64 {
    let scale = 10f64.powi(digits);
    (value * scale).round() / scale
}

/// `nodes_per_phase` for a route of `route_m`: five nodes per step of the
/// default 100 m.
fn nodes_for_route(route_m: f64) -> usize {
    let step_m = vorrt_planner::PlannerConfig::default().step_m;
    ((5.0 * route_m / step_m).ceil() as usize).max(200)
}

fn planner_for_route(route_m: f64, clearance_m: Option<f64>) -> PlannerSettings {
    let nodes = nodes_for_route(route_m);
    let default_samples = vorrt_planner::PlannerConfig::default().samples_per_phase;
    PlannerSettings {
        clearance_m,
        nodes_per_phase: Some(nodes),
        samples_per_phase: (4 * nodes > default_samples).then_some(4 * nodes),
        ..PlannerSettings::default()
    }
}

/// Where ownship and a target would be `time_s` from the start if both held
/// course and speed.
fn straight(vessel: &VesselState, time_s: f64) -> VesselState {
    vessel.advanced(time_s)
}

/// The encounter (from ownship's side) when risk of collision first arises
/// with both holding course, and when; `None` if it never does within
/// `horizon_s`.
pub fn encounter_at_risk(
    own: &VesselState,
    target: &VesselState,
    rules: &RuleParameters,
    horizon_s: f64,
) -> Option<(f64, Encounter)> {
    let step_s = 5.0;
    let steps = (horizon_s / step_s).ceil() as usize;
    (0..=steps).find_map(|step| {
        let time_s = step as f64 * step_s;
        let own_now = straight(own, time_s);
        let target_now = straight(target, time_s);
        assess_risk(&own_now, &target_now, rules)
            .at_risk
            .then(|| (time_s, classify(&own_now, &target_now, rules)))
    })
}

/// One draw of a target of type `encounter` against `own`: the target's
/// state and CPA time.
fn draw_target(
    rng: &mut ChaCha8Rng,
    spec: &OpenSeaSpec,
    own: &VesselState,
    encounter: Encounter,
) -> (VesselState, f64) {
    let own_speed_kn = units::mps_to_knots(own.speed_mps);
    let tcpa_s = 60.0 * uniform_in(rng, spec.tcpa_min);
    let cpa_m = units::nautical_miles_to_m(uniform(rng, -spec.max_cpa_nm, spec.max_cpa_nm));
    let (course_deg, speed_kn) = match encounter {
        Encounter::HeadOn => (180.0 + uniform(rng, -6.0, 6.0), uniform(rng, 8.0, 18.0)),
        Encounter::CrossingGiveWay => (uniform(rng, 205.0, 335.0), uniform(rng, 8.0, 18.0)),
        Encounter::CrossingStandOn => (uniform(rng, 25.0, 155.0), uniform(rng, 8.0, 18.0)),
        Encounter::Overtaking => (
            uniform(rng, -15.0, 15.0),
            own_speed_kn * uniform(rng, 0.4, 0.75),
        ),
        _ => (
            uniform(rng, -15.0, 15.0),
            own_speed_kn + uniform(rng, 4.0, 10.0),
        ),
    };
    let length_m = uniform(rng, 50.0, 250.0).round();
    let course_rad = angle::normalize_2pi(course_deg.to_radians());
    let speed_mps = units::knots_to_mps(speed_kn);
    let velocity = angle::velocity(course_rad, speed_mps);
    let relative = velocity - own.velocity_mps();
    let across = if relative.length() > 0.0 {
        relative.normalize().perp()
    } else {
        DVec2::X
    };
    let meet = own.position_m + own.velocity_mps() * tcpa_s + across * cpa_m;
    let start = meet - velocity * tcpa_s;
    (
        VesselState::new(start, course_rad, speed_mps, length_m),
        tcpa_s,
    )
}

/// Scenario `index` of an open-sea batch seeded with `seed` (see
/// [`OpenSeaSpec`]). Every target has risk of collision with ownship if
/// ownship holds its course, in the encounter type drawn for it; the
/// scenario is validated.
///
/// # Errors
/// [`GeneratorError::InvalidSpec`] for a bad specification,
/// [`GeneratorError::Placement`] when a target cannot be placed in
/// `max_attempts` draws.
pub fn open_sea(spec: &OpenSeaSpec, seed: u64, index: u64) -> Result<Scenario, GeneratorError> {
    spec.check()?;
    let rules = RuleParameters::default();
    let mut rng = scenario_stream(seed, index);
    let mut behaviour_rng = behaviour_stream(seed, index);
    let own_speed_kn = round_to(uniform_in(&mut rng, spec.own_speed_kn), 1);
    let goal_nm = round_to(uniform_in(&mut rng, spec.goal_distance_nm), 2);
    let ownship = VesselSpec::new("ownship", (0.0, 0.0), 0.0, own_speed_kn, OWNSHIP_LENGTH_M)
        .with_goal_nm((0.0, goal_nm));
    let own = ownship.state();
    let mut targets = Vec::with_capacity(spec.targets);
    let mut kinds = Vec::with_capacity(spec.targets);
    for number in 0..spec.targets {
        let intended = spec.mix.draw(&mut rng);
        let mut placed = None;
        for _ in 0..spec.max_attempts {
            let (drawn, tcpa_s) = draw_target(&mut rng, spec, &own, intended);
            let mut target = rounded(&drawn);
            // Bound for a point well beyond the encounter: two hours past
            // the CPA. It steers for its goal, so its course is the goal's
            // bearing from the (rounded) start.
            let goal = target.position_m + target.velocity_mps() * (tcpa_s + 7200.0);
            let goal_nm = (
                round_to(units::m_to_nautical_miles(goal.x), 3),
                round_to(units::m_to_nautical_miles(goal.y), 3),
            );
            target.course_rad = angle::unit_to_course(
                DVec2::new(
                    units::nautical_miles_to_m(goal_nm.0),
                    units::nautical_miles_to_m(goal_nm.1),
                ) - target.position_m,
            );
            if holds_as_intended(&own, &target, intended, spec, &rules) {
                placed = Some((target, goal_nm, tcpa_s));
                break;
            }
        }
        let Some((target, goal_nm, tcpa_s)) = placed else {
            return Err(GeneratorError::Placement {
                index,
                target: number,
                encounter: intended,
                attempts: spec.max_attempts,
            });
        };
        let behaviour = spec.behaviour.behaviour(&mut behaviour_rng, tcpa_s);
        targets.push(
            VesselSpec::new(
                format!("TS{}", number + 1),
                (
                    units::m_to_nautical_miles(target.position_m.x),
                    units::m_to_nautical_miles(target.position_m.y),
                ),
                target.course_rad.to_degrees(),
                units::mps_to_knots(target.speed_mps),
                target.length_m,
            )
            .with_goal_nm(goal_nm)
            .with_behaviour(behaviour),
        );
        kinds.push(intended);
    }
    let route_m = units::nautical_miles_to_m(goal_nm);
    let mut scenario = Scenario {
        name: format!(
            "open-sea-{}t-{}-s{seed}-{index:05}",
            spec.targets,
            spec.behaviour.name()
        ),
        description: Some(format!(
            "Generated open-sea encounter (seed {seed}, index {index}): ownship north at {own_speed_kn} kn for {goal_nm} nm; targets {}.",
            kinds
                .iter()
                .enumerate()
                .map(|(number, kind)| format!("TS{} {kind}", number + 1))
                .collect::<Vec<_>>()
                .join(", ")
        )),
        ownship,
        targets,
        planner: planner_for_route(route_m, None),
        simulation: Default::default(),
        lanes: Vec::new(),
        seed: Some(run_seed(seed, index)),
        source: format!("<generated open-sea seed {seed} index {index}>"),
    };
    scenario.validate()?;
    Ok(scenario)
}

/// The target as a scenario file will hold it: start in nautical miles to 4
/// decimals (0.2 m), course to 0.01°, speed to 0.01 kn.
fn rounded(target: &VesselState) -> VesselState {
    let nm = |m: f64| units::nautical_miles_to_m(round_to(units::m_to_nautical_miles(m), 4));
    VesselState::new(
        DVec2::new(nm(target.position_m.x), nm(target.position_m.y)),
        angle::normalize_2pi(round_to(target.course_rad.to_degrees(), 2).to_radians()),
        units::knots_to_mps(round_to(units::mps_to_knots(target.speed_mps), 2)),
        target.length_m,
    )
}

/// Whether a (rounded) target keeps the generator's promises: CPA under
/// `max_cpa_nm` (plus rounding) in the `tcpa_min` window, risk of collision
/// arising before the CPA, of the intended type, and a start clear of ownship.
fn holds_as_intended(
    own: &VesselState,
    target: &VesselState,
    intended: Encounter,
    spec: &OpenSeaSpec,
    rules: &RuleParameters,
) -> bool {
    let cpa = closest_point_of_approach(
        own.position_m,
        own.velocity_mps(),
        target.position_m,
        target.velocity_mps(),
    );
    let window_s = (60.0 * spec.tcpa_min.0 - 1.0, 60.0 * spec.tcpa_min.1 + 1.0);
    if !(cpa.distance_m < rules.risk_cpa_m
        && cpa.distance_m <= units::nautical_miles_to_m(spec.max_cpa_nm) + 5.0
        && cpa.time_s >= window_s.0
        && cpa.time_s <= window_s.1)
    {
        return false;
    }
    if own.range_to(target) < units::nautical_miles_to_m(0.3) {
        return false;
    }
    matches!(
        encounter_at_risk(own, target, rules, cpa.time_s),
        Some((_, encounter)) if encounter == intended
    )
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
            Lane {
                name: name.into(),
                from_nm: (from, centre),
                to_nm: (to, centre),
                width_nm: spec.lane_width_nm,
            },
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
            let centre = lane.from_nm.1;
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
        let count = ((spec.targets_per_nm * (far - near)).round() as usize).max(1);
        let centre = lane.from_nm.1;
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
    let mut scenario = Scenario {
        name: format!(
            "tss-{}-{}pnm-{}-s{seed}-{index:05}",
            spec.direction.name(),
            spec.targets_per_nm,
            spec.behaviour.name()
        ),
        description: Some(format!(
            "Generated TSS crossing (seed {seed}, index {index}): {} lane(s) {} nm wide, {} targets/nm, {} targets; ownship north at {own_speed_kn} kn; clearance 100 m.",
            lanes.len(),
            spec.lane_width_nm,
            spec.targets_per_nm,
            targets.len()
        )),
        ownship,
        targets,
        planner: planner_for_route(route_m, Some(100.0)),
        simulation: Default::default(),
        lanes: lanes.into_iter().map(|(lane, _)| lane).collect(),
        seed: Some(run_seed(seed, index)),
        source: format!("<generated tss seed {seed} index {index}>"),
    };
    scenario.validate()?;
    Ok(scenario)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn streams_differ_per_index_and_repeat() {
        let a = scenario_stream(1, 0).next_u64();
        assert_eq!(a, scenario_stream(1, 0).next_u64());
        assert_ne!(a, scenario_stream(1, 1).next_u64());
        assert_ne!(a, scenario_stream(2, 0).next_u64());
    }

    #[test]
    fn mix_with_one_weight_draws_only_that() {
        let mix = EncounterMix {
            head_on: 0.0,
            crossing_give_way: 0.0,
            crossing_stand_on: 0.0,
            overtaking: 2.0,
            being_overtaken: 0.0,
        };
        let mut rng = scenario_stream(3, 3);
        assert!((0..100).all(|_| mix.draw(&mut rng) == Encounter::Overtaking));
    }

    #[test]
    fn bad_specs_are_refused() {
        assert!(matches!(
            open_sea(&OpenSeaSpec::with_targets(0), 1, 0),
            Err(GeneratorError::InvalidSpec(_))
        ));
        assert!(matches!(
            open_sea(&OpenSeaSpec::with_targets(65), 1, 0),
            Err(GeneratorError::InvalidSpec(_))
        ));
        let mut spec = OpenSeaSpec::with_targets(2);
        spec.mix = EncounterMix {
            head_on: 0.0,
            crossing_give_way: 0.0,
            crossing_stand_on: 0.0,
            overtaking: 0.0,
            being_overtaken: 0.0,
        };
        assert!(open_sea(&spec, 1, 0).is_err());
        assert!(tss(&TssSpec::with_density(f64::NAN), 1, 0).is_err());
    }

    #[test]
    fn behaviour_names_parse() {
        for name in ["constant", "colregs", "noisy", "sudden-turn"] {
            assert_eq!(TargetBehaviour::from_name(name).unwrap().name(), name);
        }
        assert!(TargetBehaviour::from_name("wild").is_err());
    }
}
