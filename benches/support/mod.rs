//! Shared by the benchmarks: fixture loading and a deterministic encounter
//! generator.

#![allow(dead_code, unreachable_pub)]

use glam::DVec2;
use vorrt::colregs::VesselState;
use vorrt::jfs::TargetState;
use vorrt::planner::{PlannerConfig, PlanningProblem};
use vorrt::scenarios::{Scenario, fixtures};

/// The seed every benchmarked plan uses.
pub const SEED: u64 = 1;

/// The seed of the generated encounters.
pub const GENERATOR_SEED: u64 = 0x5eed_0f7a_46e7;

/// The bundled fixture `<dir>/<name>.ron` (`vorrt::scenarios::fixtures`),
/// loaded and validated.
pub fn fixture(dir: &str, name: &str) -> Scenario {
    let fixture = fixtures::find(&format!("{dir}/{name}"))
        .unwrap_or_else(|| panic!("no bundled fixture {dir}/{name}"));
    fixture
        .load()
        .unwrap_or_else(|error| panic!("{}: {error}", fixture.source()))
}

/// A fixture's planning problem and planner configuration.
pub fn fixture_problem(dir: &str, name: &str) -> (PlanningProblem, PlannerConfig) {
    let scenario = fixture(dir, name);
    let config = scenario
        .planner_config()
        .unwrap_or_else(|error| panic!("{name}: {error}"));
    (scenario.planning_problem(), config)
}

/// `SplitMix64`: a tiny, fixed, dependency-free generator, so that the
/// generated encounters never change with a dependency's version.
pub struct SplitMix64(u64);

impl SplitMix64 {
    pub fn new(seed: u64) -> Self {
        Self(seed)
    }

    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// Uniform in `[low, high)`.
    pub fn uniform(&mut self, low: f64, high: f64) -> f64 {
        #[expect(
            clippy::cast_precision_loss,
            reason = "53 random bits and 2^53: both exact in f64"
        )]
        let unit = (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64;
        low + (high - low) * unit
    }
}

const NM: f64 = 1852.0;
const KN: f64 = 1852.0 / 3600.0;

/// `targets` vessels on near-collision courses with ownship's straight route.
///
/// Ownship sails from (0, -3) nm north at 12 kn to (0, 3) nm (the paper's
/// frame). Each target picks a point of that route between 15 % and 85 % of
/// the way, the time ownship would be there, a course of 225° to 315° (a
/// stream of traffic crossing from starboard, as in the paper's traffic
/// separation scheme: ownship gives way to every target, so the rules never
/// contradict one another) and a speed of 6 to 16 kn; it starts where holding
/// that course and speed puts it at the point then, shifted sideways by up to
/// 300 m (the miss distance, under the 200 m clearance plus lengths in most
/// cases). Targets hold course and speed. Same `(targets, seed)`, same problem.
///
/// Targets from every direction (courses 0° to 360°) were tried first: from 8
/// targets on, the rules for different targets contradict one another often
/// enough that no plan exists and the planner spends its whole sample budget
/// (see `docs/performance.md`).
pub fn generated_problem(targets: usize, seed: u64) -> PlanningProblem {
    let own_speed = 12.0 * KN;
    let start = DVec2::new(0.0, -3.0 * NM);
    let goal = DVec2::new(0.0, 3.0 * NM);
    let own = VesselState::new(start, 0.0, own_speed, 100.0);
    let route = goal - start;
    let mut rng = SplitMix64::new(seed);
    let vessels = (0..targets)
        .map(|_| {
            let fraction = rng.uniform(0.15, 0.85);
            let meeting = start + route * fraction;
            let meeting_time = route.length() * fraction / own_speed;
            let course = rng.uniform(225f64.to_radians(), 315f64.to_radians());
            let target_speed = rng.uniform(6.0, 16.0) * KN;
            let heading = DVec2::new(course.sin(), course.cos());
            let sideways = DVec2::new(heading.y, -heading.x) * rng.uniform(-300.0, 300.0);
            let position = meeting + sideways - heading * target_speed * meeting_time;
            let length = rng.uniform(50.0, 200.0);
            TargetState::constant_velocity(VesselState::new(position, course, target_speed, length))
        })
        .collect();
    PlanningProblem::new(own, goal, vessels)
}

/// A problem whose goal cannot be reached: `generated_problem(1, seed)` with a
/// stationary vessel parked on ownship's goal. Every phase then grows its tree
/// to the full `nodes_per_phase` (given samples enough), so that the plan's
/// time measures the cost of a tree of that size.
pub fn blocked_goal_problem(seed: u64) -> PlanningProblem {
    let mut problem = generated_problem(1, seed);
    let blocker = VesselState::new(problem.goal_m, 0.0, 0.0, 100.0);
    problem
        .targets
        .push(TargetState::constant_velocity(blocker));
    problem
}

/// The configuration for [`blocked_goal_problem`]: `nodes_per_phase` nodes
/// in each of the two phases, samples enough to grow them, no restart.
pub fn blocked_goal_config(nodes_per_phase: usize) -> PlannerConfig {
    PlannerConfig {
        nodes_per_phase,
        samples_per_phase: 100 * nodes_per_phase,
        max_restarts: 0,
        ..PlannerConfig::default()
    }
}
