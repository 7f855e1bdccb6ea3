//! Tests of planning in the closed loop.
use super::*;
use vorrt_colregs::Encounter;

#[test]
fn a_return_foreseen_anew_or_moved_asks_again() {
    assert!(!return_moved(None, None));
    assert!(return_moved(None, Some(200.0)), "a return now foreseen");
    assert!(return_moved(Some(20.0), None), "no longer foreseen");
    assert!(!return_moved(Some(100.0), Some(100.0 + RETURN_MOVED_S)));
    assert!(return_moved(
        Some(100.0),
        Some(100.0 + RETURN_MOVED_S + 5.0)
    ));
}

fn latch(encounter: Encounter) -> EncounterLatch {
    EncounterLatch {
        encounter,
        reference_course_rad: 0.0,
        reference_speed_mps: 6.0,
        latched_at_s: 0.0,
        risk_distance_m: None,
    }
}

#[test]
fn a_retry_is_due_after_the_wait_or_when_the_encounters_change() {
    let mut retry = RetryTimer::idle();
    let situation = vec![Some(latch(Encounter::HeadOn)), None];
    assert!(!retry.due(1e9, &situation), "nothing failed yet");
    retry.failed(100.0, &situation);
    assert!(!retry.due(100.0 + RETRY_AFTER_S - 5.0, &situation));
    assert!(retry.due(100.0 + RETRY_AFTER_S, &situation));
    // An encounter released, or a new one latched: due at once.
    assert!(retry.due(105.0, &[None, None]));
    assert!(retry.due(
        105.0,
        &[
            Some(latch(Encounter::HeadOn)),
            Some(latch(Encounter::Overtaking))
        ]
    ));
    retry.succeeded();
    assert!(!retry.due(1e9, &[None, None]));
}

#[test]
fn the_wait_doubles_while_retries_keep_the_plan_in_force_and_starts_again_after_a_plan() {
    let mut retry = RetryTimer::idle();
    let situation = vec![Some(latch(Encounter::HeadOn)), None];
    retry.failed(0.0, &situation);
    assert!(retry.due(RETRY_AFTER_S, &situation));
    // Retry after retry finds nothing better: 40, 80, 160 s, then no longer.
    let mut time_s = RETRY_AFTER_S;
    for doublings in 1..=RETRY_DOUBLINGS + 2 {
        retry.kept(time_s, &situation);
        let wait_s = RETRY_AFTER_S * f64::from(1_u32 << doublings.min(RETRY_DOUBLINGS));
        assert!(!retry.due(time_s + wait_s - 5.0, &situation), "{doublings}");
        assert!(retry.due(time_s + wait_s, &situation), "{doublings}");
        time_s += wait_s;
    }
    assert!((RETRY_AFTER_S * f64::from(1_u32 << RETRY_DOUBLINGS) - 160.0).abs() < 1e-9);
    // A change of the encounters in force still asks at once.
    assert!(retry.due(time_s + 5.0, &[None, None]));
    // A plan put in force (a fallback found anew): the wait starts again.
    retry.failed(time_s, &situation);
    assert!(retry.due(time_s + RETRY_AFTER_S, &situation));
}

#[test]
fn a_fallback_level_that_would_repeat_the_failed_search_is_not_asked() {
    use glam::DVec2;
    use vorrt_planner::PlannerConfig;
    // A vessel lies stopped on the goal, and no encounter is ever
    // latched (MTD 1 m): every level refuses only for safety, so the
    // weaker levels would draw the same samples and fail alike.
    let own = VesselState::new(DVec2::ZERO, 0.0, 6.0, 50.0);
    let goal_m = DVec2::new(0.0, 3000.0);
    let blocker = TargetState::constant_velocity(VesselState::new(goal_m, 0.0, 0.0, 50.0));
    let problem = PlanningProblem::new(own, goal_m, vec![blocker]);
    let mut config = PlannerConfig {
        nodes_per_phase: 40,
        samples_per_phase: 40,
        nodes_per_route_step: 0.0,
        max_restarts: 1,
        ..PlannerConfig::default()
    };
    config.rules.mtd_m = 1.0;
    let mut planners: Vec<Planner> = [
        Compliance::Full,
        Compliance::Directions,
        Compliance::SafetyOnly,
    ]
    .into_iter()
    .map(|compliance| {
        Planner::new(PlannerConfig {
            compliance,
            ..config
        })
        .expect("valid")
    })
    .collect();
    let one_search = Planner::new(config)
        .expect("valid")
        .plan(&problem, 9)
        .expect_err("blocked")
        .statistics()
        .expect("statistics")
        .samples;
    let (mut active, mut plans, mut retry) = (None, Vec::new(), RetryTimer::idle());
    let model = OwnshipModel::Instant(vorrt_jfs::InstantTurn { max_turn_rad: 0.5 });
    plan_now(
        &mut planners,
        &problem,
        &model,
        &PlanCall {
            why: PlanTrigger::Initial,
            seed: 9,
            clearance_m: config.clearance_m,
            speed_change_mps2: 0.01,
        },
        &mut active,
        &mut plans,
        &mut retry,
    );
    let event = plans.last().expect("one call");
    assert!(!event.succeeded);
    // One search drawn, not three.
    assert_eq!(event.samples_drawn, one_search);
    assert!(active.is_some_and(|active| active.evasive));
}

/// The closed loop's fallback once every level failed, with a straight plan
/// north to (0, 5000) in force, ownship (50 m) at 6 m/s, one target as
/// given, and a clearance no course can keep (1000 m): what is put in force.
fn fall_back_with(target: TargetState) -> (ActivePlan, PlanEvent) {
    use glam::DVec2;
    use vorrt_planner::PlannerConfig;
    let own = VesselState::new(DVec2::ZERO, 0.0, 6.0, 50.0);
    let goal_m = DVec2::new(0.0, 5000.0);
    let straight = Planner::new(PlannerConfig::default())
        .expect("valid")
        .plan(&PlanningProblem::new(own, goal_m, Vec::new()), 1)
        .expect("open water");
    let problem = PlanningProblem::new(own, goal_m, vec![target]);
    let config = PlannerConfig {
        clearance_m: 1000.0,
        ..PlannerConfig::default()
    };
    let planners = vec![Planner::new(config).expect("valid")];
    assert!(
        planners[0]
            .check_legs(&problem, &remaining_legs(&straight, 0.0))
            .is_err(),
        "the plan in force no longer passes the check"
    );
    let mut active = Some(ActivePlan {
        anticipated: vec![Vec::new()],
        plan: straight,
        compliance: Compliance::Full,
        predicted_at_s: 0.0,
        predicted: problem.targets.clone(),
        encounters_seen: false,
        evasive: false,
        evasion: None,
    });
    let mut plans = Vec::new();
    let model = OwnshipModel::Instant(vorrt_jfs::InstantTurn { max_turn_rad: 0.5 });
    fall_back(
        &planners,
        &problem,
        &model,
        &PlanCall {
            why: PlanTrigger::Retry,
            seed: 1,
            clearance_m: config.clearance_m,
            speed_change_mps2: 0.01,
        },
        &mut active,
        &mut plans,
        Attempts {
            first_error: None,
            spent: PlanStatistics::default(),
            samples_drawn: 0,
        },
    );
    (
        active.expect("something in force"),
        plans.pop().expect("the call recorded"),
    )
}

#[test]
fn a_plan_in_force_that_keeps_nearly_as_far_as_any_evasive_course_is_held() {
    use glam::DVec2;
    // A vessel 412 m off the starboard quarter, drawing away east: every
    // course keeps what the range is now, no more, and none keeps 1000 m.
    // The plan under way keeps as far as the best evasive course: it is
    // held (decision 56), not swapped for a turn and a stop (runs 300 and
    // 704 of the campaigns with 16 and 8 COLREGs-obeying targets: the
    // evasive manoeuvre, chosen by a few metres of a return predicted with
    // its margin, passed the overtaking vessel closer than the plan would).
    let away = TargetState::constant_velocity(VesselState::new(
        DVec2::new(400.0, -100.0),
        std::f64::consts::FRAC_PI_2,
        6.0,
        50.0,
    ));
    let (active, event) = fall_back_with(away);
    assert!(!active.evasive, "the plan in force is held");
    assert!(!active.plan.legs.is_empty());
    assert_eq!(event.evasive_course_deg, None);
    assert!(!event.succeeded);
    assert_eq!(event.compliance, Compliance::SafetyOnly);
}

#[test]
fn a_plan_in_force_expected_to_touch_gives_way_to_the_evasive_manoeuvre() {
    use glam::DVec2;
    // Head-on, 1500 m ahead: the straight plan runs into the vessel, and
    // turning away keeps clearly farther; the evasive manoeuvre is taken.
    let head_on = TargetState::constant_velocity(VesselState::new(
        DVec2::new(0.0, 1500.0),
        std::f64::consts::PI,
        6.0,
        50.0,
    ));
    let (active, event) = fall_back_with(head_on);
    assert!(active.evasive);
    assert!(event.evasive_course_deg.is_some());
}
