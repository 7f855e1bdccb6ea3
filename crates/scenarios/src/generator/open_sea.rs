//! Open-sea encounters: targets on near-collision courses with ownship in a
//! chosen mix of encounter types.

use super::random::{behaviour_stream, round_to, run_seed, scenario_stream, uniform, uniform_in};
use super::verification::holds_as_intended;
use super::{
    GeneratorError, MAX_GENERATED_TARGETS, OWNSHIP_LENGTH_M, TargetBehaviour, check_range,
    planner_for_route,
};
use crate::scenario::{Scenario, VesselSpec};
use glam::DVec2;
use rand_chacha::ChaCha8Rng;
use serde::{Deserialize, Serialize};
use vorrt_colregs::{Encounter, RuleParameters, VesselState};
use vorrt_geometry::{angle, units};

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

    pub(super) fn check(&self) -> Result<(), GeneratorError> {
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

    pub(super) fn draw(&self, rng: &mut ChaCha8Rng) -> Encounter {
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

    pub(super) fn check(&self) -> Result<(), GeneratorError> {
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
        targets,
        planner: planner_for_route(route_m, None),
        seed: Some(run_seed(seed, index)),
        source: format!("<generated open-sea seed {seed} index {index}>"),
        ..Scenario::new(String::new(), ownship)
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
