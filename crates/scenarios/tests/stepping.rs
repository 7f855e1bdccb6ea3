//! The closed loop as a value: stepping it by hand gives the record
//! `simulate` gives, each step says what ownship decided, and a target can
//! follow a recording, seen by ownship's planner only as it is at present.

use std::path::PathBuf;
use vorrt_colregs::VesselState;
use vorrt_scenarios::{
    Behaviour, ClosedLoop, Decision, PlanTrigger, RecordedMotion, RunStatus, Scenario,
    SimulationRecord, StepOutcome, TimedState, simulate,
};

fn fixture(relative: &str) -> Scenario {
    let path: PathBuf = [env!("CARGO_MANIFEST_DIR"), "fixtures", relative]
        .iter()
        .collect();
    Scenario::load(&path).expect("fixture loads")
}

/// The record without the planner's wall-clock times, which differ from
/// run to run.
fn without_clock(mut record: SimulationRecord) -> SimulationRecord {
    for event in &mut record.plans {
        event.statistics.elapsed_s = 0.0;
    }
    for check in &mut record.plans_kept {
        check.search_time_s = 0.0;
    }
    record
}

/// Steps `run` to its end by hand, checking every moment against the record
/// so far, and gives the record.
#[expect(
    clippy::float_cmp,
    reason = "stepping by hand gives exactly the times `simulate` gives"
)]
#[expect(clippy::cast_precision_loss, reason = "a step count, far below 2^52")]
fn step_by_hand(mut run: ClosedLoop) -> SimulationRecord {
    let time_step_s = run.record().time_step_s;
    let (mut planned, mut kept) = (0, 0);
    while let Some(outcome) = run.step() {
        let state = run.state();
        let record = run.record();
        assert_eq!(state.time_s, outcome.time_s);
        assert_eq!(state.step as f64 * time_step_s, outcome.time_s);
        assert_eq!(Some(&outcome.time_s), record.times_s.last());
        assert!((outcome.time_s - outcome.from_s - time_step_s).abs() < 1e-9);
        assert_eq!(Some(&state.ownship), record.ownship.last());
        for (target, track) in state.targets.iter().zip(&record.targets) {
            assert_eq!(Some(target), track.last());
        }
        assert_eq!(state.target_names, record.target_names.as_slice());
        assert_eq!(state.encounters.len(), state.targets.len());
        assert_eq!(state.status, outcome.status);
        assert_eq!(run.is_finished(), outcome.status.is_finished());
        match outcome.decision {
            Decision::Planned(trigger) => {
                planned += 1;
                let event = record.plans.last().expect("a call recorded");
                assert_eq!((event.time_s, event.trigger), (outcome.from_s, trigger));
            }
            Decision::KeptPlan(trigger) => {
                kept += 1;
                let check = record.plans_kept.last().expect("a check recorded");
                assert_eq!((check.time_s, check.trigger), (outcome.from_s, trigger));
            }
            Decision::SailedOn => {}
        }
        assert_eq!(record.plans.len(), planned);
        assert_eq!(record.plans_kept.len(), kept);
    }
    assert!(run.is_finished());
    assert!(run.step().is_none(), "a finished run steps no more");
    run.finish()
}

#[test]
fn stepping_by_hand_gives_the_record_simulate_gives() {
    let noisy = Behaviour::Noisy {
        course_sigma_deg: 5.0,
        speed_sigma_kn: 0.5,
    };
    let cases = [
        ("paper/head_on.ron", None, 1),
        ("paper/crossing.ron", Some(Behaviour::Colregs), 2),
        ("paper/multi_vessel.ron", Some(noisy), 3),
        ("imazu/imazu_14.ron", None, 1),
        ("imazu/imazu_22.ron", Some(noisy), 2),
    ];
    for (relative, behaviour, seed) in cases {
        let mut scenario = fixture(relative);
        if let Some(behaviour) = behaviour {
            for target in &mut scenario.targets {
                target.behaviour = behaviour;
            }
        }
        let by_hand = step_by_hand(ClosedLoop::new(&scenario, seed).expect("valid"));
        let simulated = simulate(&scenario, seed).expect("valid");
        assert!(!by_hand.plans.is_empty(), "{relative}");
        assert_eq!(
            without_clock(by_hand),
            without_clock(simulated),
            "{relative}"
        );
    }
}

#[test]
#[expect(clippy::float_cmp, reason = "the test pins exact results")]
fn a_run_is_finished_at_its_goal_or_when_its_time_is_up() {
    let mut scenario = fixture("paper/head_on.ron");
    scenario.simulation.max_duration_s = Some(60.0);
    let mut run = ClosedLoop::new(&scenario, 1).expect("valid");
    let mut last = None;
    while let Some(outcome) = run.step() {
        last = Some(outcome);
    }
    let last = last.expect("steps");
    assert_eq!(last.status, RunStatus::OutOfTime);
    assert_eq!(last.time_s, 60.0);
    // An outcome is plain data, for a viewer or a binding.
    let json = serde_json::to_string(&last).expect("serialises");
    assert!(json.contains("\"out_of_time\""), "{json}");
    let back: StepOutcome = serde_json::from_str(&json).expect("reads back");
    assert_eq!(back, last);
    let record = run.finish();
    assert!(!record.reached_goal);
    assert_eq!(record.times_s.len(), 13);
    // At its start the run is at time 0, before any plan.
    let run = ClosedLoop::new(&scenario, 1).expect("valid");
    let state = run.state();
    assert_eq!((state.time_s, state.step), (0.0, 0));
    assert_eq!(state.status, RunStatus::Running);
    assert!(state.plan.is_none() && !state.evasive);
    assert_eq!(run.finish().times_s, vec![0.0]);
}

#[test]
fn one_motion_per_target_is_required() {
    let scenario = fixture("paper/multi_vessel.ron");
    let config = scenario.planner_config().expect("valid");
    let mut motions = ClosedLoop::scenario_motions(&scenario, 1);
    assert_eq!(motions.len(), scenario.targets.len());
    motions.pop();
    let error = ClosedLoop::with_motions(&scenario, &config, 1, motions).expect_err("one short");
    assert_eq!(error.field(), Some("targets"));
}

/// The crossing target's recording, a state every 60 s for 40 minutes: west
/// at its speed until `turn_at_s`, then on `then_course_deg`.
fn crossing_recording(
    scenario: &Scenario,
    turn_at_s: f64,
    then_course_deg: f64,
) -> Vec<TimedState> {
    let start = scenario.targets[0].state();
    let then = VesselState {
        course_rad: then_course_deg.to_radians(),
        ..start
    };
    (0..=40)
        .map(|minute| {
            let time_s = 60.0 * f64::from(minute);
            let vessel = if time_s <= turn_at_s {
                start.advanced(time_s)
            } else {
                VesselState {
                    position_m: start.advanced(turn_at_s).position_m,
                    ..then
                }
                .advanced(time_s - turn_at_s)
            };
            TimedState { time_s, vessel }
        })
        .collect()
}

/// A run of the crossing with its target moved by `states`.
fn crossing_with(scenario: &Scenario, states: Vec<TimedState>) -> ClosedLoop {
    let config = scenario.planner_config().expect("valid");
    let mut motions = ClosedLoop::scenario_motions(scenario, 1);
    motions[0] = Box::new(RecordedMotion::new(states).expect("a valid recording"));
    ClosedLoop::with_motions(scenario, &config, 1, motions).expect("valid")
}

#[test]
#[expect(clippy::float_cmp, reason = "the test pins exact results")]
fn a_recorded_target_is_where_the_recording_says_at_every_step() {
    let scenario = fixture("paper/crossing.ron");
    // It turns 40° to port after 5 minutes, toward ownship's route.
    let states = crossing_recording(&scenario, 300.0, 230.0);
    let mut run = crossing_with(&scenario, states.clone());
    let mut steps = 0;
    loop {
        let state = run.state();
        let time_s = state.time_s;
        let target = state.targets[0];
        // The recorded states around `time_s`, a minute apart.
        #[expect(
            clippy::cast_possible_truncation,
            clippy::cast_sign_loss,
            reason = "a non-negative run time of minutes, floored"
        )]
        let minute = (time_s / 60.0).floor() as usize;
        let from = &states[minute];
        if from.time_s == time_s {
            assert_eq!(target, from.vessel, "at {time_s} s, a recorded state");
        } else {
            let to = &states[minute + 1];
            let fraction = (time_s - from.time_s) / 60.0;
            let expected =
                from.vessel.position_m + (to.vessel.position_m - from.vessel.position_m) * fraction;
            assert!(
                target.position_m.distance(expected) < 1e-6,
                "at {time_s} s: {:?}, not {expected:?}",
                target.position_m
            );
            assert!((target.speed_mps - from.vessel.speed_mps).abs() < 1e-9);
        }
        assert_eq!(state.target_names[0], "TS1");
        if run.step().is_none() {
            break;
        }
        steps += 1;
    }
    assert!(steps > 100, "{steps} steps");
    let record = run.finish();
    assert!(record.reached_goal);
    // Ownship saw it turn off its prediction and planned again.
    assert!(
        record.replans() + record.plans_kept.len() > 0,
        "{:?}",
        record.triggers()
    );
    assert!(!vorrt_scenarios::evaluate(&scenario, &record).collision);
}

#[test]
#[expect(clippy::float_cmp, reason = "the test pins exact results")]
fn ownship_plans_from_the_recordings_present_never_its_future() {
    let scenario = fixture("paper/crossing.ron");
    // Two recordings alike for the first 5 minutes; then one holds on west,
    // the other turns hard to port across ownship's route.
    let turn_at_s = 300.0;
    let held = crossing_with(&scenario, crossing_recording(&scenario, turn_at_s, 270.0)).run();
    let turned = crossing_with(&scenario, crossing_recording(&scenario, turn_at_s, 200.0)).run();
    let (held, turned) = (without_clock(held), without_clock(turned));
    let before = |record: &SimulationRecord| {
        let calls: Vec<_> = record
            .plans
            .iter()
            .filter(|event| event.time_s <= turn_at_s)
            .cloned()
            .collect();
        let steps = record
            .times_s
            .iter()
            .take_while(|&&time_s| time_s <= turn_at_s)
            .count();
        (
            calls,
            record
                .plans_kept
                .iter()
                .filter(|kept| kept.time_s <= turn_at_s)
                .count(),
            record.ownship[..steps].to_vec(),
        )
    };
    // Until the recordings part, ownship was given the same targets, so it
    // planned and sailed alike: nothing of the turn to come reached it.
    assert!(!before(&held).0.is_empty());
    assert_eq!(before(&held), before(&turned));
    // The turn is seen once it is made, as the target leaves the course it
    // was predicted on from its present state; a prediction that drew on
    // the recording's future would have foreseen it.
    // (Once the crossing is past and clear, ownship asks whether a sooner
    // plan exists, decision 52: that question is not about the recording.)
    let about_the_targets = |record: &SimulationRecord| -> Vec<(f64, PlanTrigger)> {
        record
            .triggers()
            .into_iter()
            .filter(|(_, trigger)| *trigger != PlanTrigger::PastAndClear)
            .collect()
    };
    assert_eq!(about_the_targets(&held), vec![(0.0, PlanTrigger::Initial)]);
    let seen = about_the_targets(&turned)[1];
    assert!(seen.0 > turn_at_s, "{:?}", turned.triggers());
    assert_eq!(seen.1, PlanTrigger::TargetOffPrediction { target: 0 });
    let at_turn = held
        .times_s
        .iter()
        .position(|&time_s| time_s == turn_at_s)
        .expect("a step at the turn");
    assert_eq!(held.targets[0][at_turn], turned.targets[0][at_turn]);
    assert_ne!(held.targets[0][at_turn + 1], turned.targets[0][at_turn + 1]);
}

#[test]
fn the_first_plan_knows_only_the_reports_made_before_it() {
    let scenario = fixture("paper/crossing.ron");
    let start = scenario.targets[0].state();
    // Reported 30 s before the start on its course; its next report, 30 s
    // into the run, says either that it held on or that it turned 60° to
    // port. Interpolating between the two reports would show the turn half
    // made at the start; AIS shows only the report before it.
    let report = |course_change_deg: f64| {
        let before = TimedState {
            time_s: -30.0,
            vessel: start.advanced(-30.0),
        };
        let after = TimedState {
            time_s: 30.0,
            vessel: VesselState {
                course_rad: start.course_rad - course_change_deg.to_radians(),
                ..start.advanced(30.0)
            },
        };
        vec![before, after]
    };
    let first_plan = |states| {
        let mut run = crossing_with(&scenario, states);
        run.step();
        without_clock(run.finish()).plans.remove(0)
    };
    let (held, turned) = (first_plan(report(0.0)), first_plan(report(60.0)));
    assert!(held.succeeded);
    assert_eq!(held, turned);
}
