//! The premises of two shortcuts that must not change a verdict
//! (`docs/decisions/0026-searches-that-repeat-nothing.md`):
//! a weaker level of the graded fallback judges a leg as a stricter one
//! does unless the stricter one refused it for a duty the weaker one drops
//! (`Compliance::checks`), and a leg valid at a wider clearance is valid at
//! `d_th`.

use glam::DVec2;
use proptest::prelude::*;
use vorrt_colregs::{EncounterLatch, VesselState, update_latch};
use vorrt_jfs::{LinearTrack, MotionModel, Pose, RateLimitedTurn, TargetState};
use vorrt_planner::safety::SafetyChecker;
use vorrt_planner::validity::{EncounterState, MotionValidator};
use vorrt_planner::{Compliance, PlannerConfig, RejectionCause};

/// Ownship at the origin heading north at 6 m/s; targets around it, the
/// encounters latched as a closed loop would; a leg turning onto a course
/// and holding it, at full or reduced speed.
fn situation() -> impl Strategy<Value = (Vec<TargetState>, f64, f64, f64)> {
    let target = (
        -6000.0..6000.0f64,
        -6000.0..6000.0f64,
        0.0..360.0f64,
        0.0..8.0f64,
    )
        .prop_map(|(east_m, north_m, course_deg, speed_mps)| {
            TargetState::constant_velocity(VesselState::new(
                DVec2::new(east_m, north_m),
                course_deg.to_radians(),
                speed_mps,
                100.0,
            ))
        });
    (
        prop::collection::vec(target, 1..4),
        -120.0..120.0f64,
        100.0..4000.0f64,
        prop::sample::select(vec![1.0, 0.45]),
    )
}

fn verdict(
    config: &PlannerConfig,
    tracks: &[LinearTrack],
    latches: &[Option<EncounterLatch>],
    alteration_deg: f64,
    hold_m: f64,
    speed_factor: f64,
) -> Result<(), RejectionCause> {
    let own = VesselState::new(DVec2::ZERO, 0.0, 6.0, 100.0);
    let checker = SafetyChecker::new(config, tracks, own, DVec2::new(0.0, 20_000.0), 0.0);
    let model = RateLimitedTurn {
        turn_radius_m: 400.0,
    };
    let leg = model
        .turn_onto(
            Pose {
                position_m: DVec2::ZERO,
                course_rad: 0.0,
            },
            alteration_deg.to_radians(),
            6.0 * speed_factor,
            hold_m,
        )
        .from_speed(6.0, 0.02);
    let mut state = EncounterState::new(latches.to_vec(), vec![0.0; tracks.len()]);
    checker.validate(&leg, 0.0, &mut state)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn a_weaker_level_repeats_every_verdict_it_can(
        (targets, alteration_deg, hold_m, factor) in situation()
    ) {
        let own = VesselState::new(DVec2::ZERO, 0.0, 6.0, 100.0);
        let full = PlannerConfig::default();
        let tracks: Vec<LinearTrack> = targets.iter().map(TargetState::track).collect();
        let latches: Vec<Option<EncounterLatch>> = targets
            .iter()
            .map(|target| update_latch(None, &own, &target.vessel, 0.0, &full.rules))
            .collect();
        let levels = [Compliance::Full, Compliance::Directions, Compliance::SafetyOnly];
        let verdicts: Vec<_> = levels
            .iter()
            .map(|&compliance| {
                let config = PlannerConfig { compliance, ..full };
                verdict(&config, &tracks, &latches, alteration_deg, hold_m, factor)
            })
            .collect();
        for stricter in 0..levels.len() {
            for weaker in stricter + 1..levels.len() {
                match verdicts[stricter] {
                    Ok(()) => prop_assert_eq!(verdicts[weaker], Ok(())),
                    Err(cause) if levels[weaker].checks(cause) => {
                        prop_assert_eq!(verdicts[weaker], Err(cause));
                    }
                    Err(_) => {}
                }
            }
        }
    }

    #[test]
    fn a_leg_valid_at_a_wider_clearance_is_valid_at_d_th(
        (targets, alteration_deg, hold_m, factor) in situation(),
        wider in 1.0..3.0f64,
    ) {
        let own = VesselState::new(DVec2::ZERO, 0.0, 6.0, 100.0);
        let floor = PlannerConfig::default();
        let preferred = PlannerConfig { clearance_m: floor.clearance_m * wider, ..floor };
        let tracks: Vec<LinearTrack> = targets.iter().map(TargetState::track).collect();
        let latches: Vec<Option<EncounterLatch>> = targets
            .iter()
            .map(|target| update_latch(None, &own, &target.vessel, 0.0, &floor.rules))
            .collect();
        if verdict(&preferred, &tracks, &latches, alteration_deg, hold_m, factor).is_ok() {
            prop_assert_eq!(verdict(&floor, &tracks, &latches, alteration_deg, hold_m, factor), Ok(()));
        }
    }
}
