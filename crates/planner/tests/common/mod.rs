//! What the property tests of the planner share: the generated encounters'
//! geometry, the test configuration, and the independent checks of a plan
//! as sailed (clearance by CPA, rate of turn, crossing ahead).

use glam::DVec2;
use proptest::prelude::*;
use vorrt_colregs::{VesselState, crosses_ahead};
use vorrt_geometry::angle;
use vorrt_geometry::cpa::cpa_clamped;
use vorrt_jfs::TargetState;
use vorrt_planner::{Plan, PlannerConfig, PlanningProblem};

/// A nautical mile, metres.
pub(crate) const NM: f64 = 1852.0;
/// A knot, m/s.
pub(crate) const KNOT: f64 = 1852.0 / 3600.0;

/// Proptest cases per property: few in the debug build, many with
/// `VORRT_HEAVY_TESTS=1`.
pub(crate) fn cases() -> u32 {
    if std::env::var("VORRT_HEAVY_TESTS").is_ok_and(|value| value == "1") {
        512
    } else {
        32
    }
}

/// The planner configuration the properties plan with.
pub(crate) fn config() -> PlannerConfig {
    PlannerConfig {
        nodes_per_phase: 400,
        ..PlannerConfig::default()
    }
}

/// Ownship at the origin heading north at `own_speed` (m/s); a target on
/// `course_deg` at `target_speed` that would pass `miss_m` from ownship
/// after they have closed about `range_nm` at their relative speed; the
/// goal 2 nm beyond the meeting point.
pub(crate) fn collision_course(
    own_speed: f64,
    course_deg: f64,
    target_speed: f64,
    range_nm: f64,
    miss_m: f64,
) -> PlanningProblem {
    let course = course_deg.to_radians();
    let target_velocity = angle::velocity(course, target_speed);
    let closing = (DVec2::new(0.0, own_speed) - target_velocity).length();
    let meet_s = range_nm * NM / closing;
    let meeting = DVec2::new(miss_m, own_speed * meet_s);
    let start = meeting - target_velocity * meet_s;
    let own = VesselState::new(DVec2::ZERO, 0.0, own_speed, 60.0);
    let target =
        TargetState::constant_velocity(VesselState::new(start, course, target_speed, 80.0));
    PlanningProblem::new(own, DVec2::new(0.0, meeting.y + 2.0 * NM), vec![target])
}

/// Every `SAMPLE_S` seconds the plan is sampled as sailed (arcs included).
pub(crate) const SAMPLE_S: f64 = 1.0;

/// Ownship's pose every `SAMPLE_S` along the plan, from its own closed-form
/// legs: `(time, position, course)`.
#[expect(
    clippy::cast_possible_truncation,
    clippy::cast_sign_loss,
    clippy::cast_precision_loss,
    reason = "a plan's duration is finite and positive, a few thousand samples"
)]
pub(crate) fn sailed(plan: &Plan) -> Vec<(f64, DVec2, f64)> {
    let first = plan.waypoints[0].time_s;
    let last = plan.waypoints.last().unwrap().time_s;
    let steps = ((last - first) / SAMPLE_S).ceil() as usize;
    (0..=steps)
        .map(|step| {
            let time = (first + step as f64 * SAMPLE_S).min(last);
            let (position, course) = plan.position_at(time).unwrap();
            (time, position, course)
        })
        .collect()
}

/// The smallest distance between the sailed path and the target's predicted
/// motion: between consecutive samples both move straight (ownship along the
/// chord, which lies within `R (1 - cos(ω SAMPLE_S / 2))`, a few millimetres,
/// of its arc), and the geometry crate's CPA gives the closest approach.
pub(crate) fn min_clearance(plan: &Plan, target: &TargetState, start_time_s: f64) -> f64 {
    sailed(plan)
        .windows(2)
        .map(|pair| {
            let ((from_s, from_m, _), (to_s, to_m, _)) = (pair[0], pair[1]);
            let duration = to_s - from_s;
            let target_then = target.predict(from_s - start_time_s).vessel;
            let own_velocity = if duration > 0.0 {
                (to_m - from_m) / duration
            } else {
                DVec2::ZERO
            };
            cpa_clamped(
                from_m - target_then.position_m,
                own_velocity - target_then.velocity_mps(),
                duration.max(0.0),
            )
            .distance_m
        })
        .fold(f64::INFINITY, f64::min)
}

/// The largest rate of turn along the sailed path, radians per second.
pub(crate) fn max_turn_rate(plan: &Plan) -> f64 {
    sailed(plan)
        .windows(2)
        .filter(|pair| pair[1].0 > pair[0].0)
        .map(|pair| angle::signed_turn(pair[0].2, pair[1].2).abs() / (pair[1].0 - pair[0].0))
        .fold(0.0, f64::max)
}

/// Whether ownship crosses the target's track ahead of the target during
/// some segment: `crosses_ahead` holds for the segment's velocity and the
/// side of the target's track ownship is on changes within the segment.
pub(crate) fn crosses_ahead_anywhere(plan: &Plan, target: &TargetState) -> bool {
    let first = plan.waypoints[0].time_s;
    plan.waypoints.windows(2).any(|pair| {
        let (from, to) = (pair[0], pair[1]);
        let duration = to.time_s - from.time_s;
        if duration <= 0.0 {
            return false;
        }
        let velocity = (to.position_m - from.position_m) / duration;
        let before = target.predict(from.time_s - first).vessel;
        let after = target.predict(to.time_s - first).vessel;
        let heading = before.velocity_mps().normalize_or_zero();
        let side_before = vorrt_geometry::cross(heading, from.position_m - before.position_m);
        let side_after = vorrt_geometry::cross(heading, to.position_m - after.position_m);
        side_before.signum() != side_after.signum()
            && crosses_ahead(
                from.position_m,
                velocity,
                before.position_m,
                before.velocity_mps(),
            )
    })
}

/// A fixed sample of [`cases`] values of `strategy`, drawn with `ChaCha` from
/// a seed made of `key`.
pub(crate) fn fixed_sample<S: Strategy>(strategy: &S, key: u8) -> Vec<S::Value> {
    use proptest::strategy::ValueTree;
    use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};
    let mut runner = TestRunner::new_with_rng(
        Config::default(),
        TestRng::from_seed(RngAlgorithm::ChaCha, &[key; 32]),
    );
    (0..cases())
        .map(|_| strategy.new_tree(&mut runner).unwrap().current())
        .collect()
}

/// Ownship's planned speed every `SAMPLE_S` along the plan: `(time, speed)`.
pub(crate) fn speeds(plan: &Plan) -> Vec<(f64, f64)> {
    sailed(plan)
        .iter()
        .map(|(time, _, _)| (*time, plan.speed_at(*time).unwrap()))
        .collect()
}

/// Whether the planned speed stays within the service speed and changes no
/// faster than `rate_mps2` between samples.
pub(crate) fn speed_profile_kept(
    plan: &Plan,
    service_mps: f64,
    rate_mps2: f64,
) -> Result<(), String> {
    let speeds = speeds(plan);
    if let Some((time, speed)) = speeds.iter().find(|(_, speed)| *speed > service_mps + 1e-9) {
        return Err(format!(
            "{speed} m/s at {time} s, above the service speed {service_mps}"
        ));
    }
    for pair in speeds.windows(2) {
        let ((from_s, from), (to_s, to)) = (pair[0], pair[1]);
        if (to - from).abs() > rate_mps2 * (to_s - from_s) + 1e-9 {
            return Err(format!(
                "speed {from} -> {to} m/s in {} s at {from_s} s",
                to_s - from_s
            ));
        }
    }
    Ok(())
}
